//! Modes of a linear model ẋ = A x: eigenvalues, eigenvectors, and what each mode means.
//!
//! The eigenvalues come from nalgebra's real Schur form. A real matrix that is not symmetric
//! has complex eigenvectors, which nalgebra does not give; each is found by inverse iteration
//! on A − λI in complex arithmetic, with λ moved off the eigenvalue by 10⁻¹⁰ of the spectral
//! radius so that the solve is defined (three iterations take the error in the vector to the
//! square of that ratio and below). A mode is one real eigenvalue or one pair of conjugate
//! ones, listed once, with its period 2π/|Im λ| (as seen in space, where the state measures
//! roll and pitch in axes that turn with the heading), damping ratio −Re λ/|λ|, time to double
//! ln 2/Re λ or to half ln 2/(−Re λ), the states whose share of the eigenvector is at least
//! half the largest, and a name where the family knows one.

use crate::models::Family;
use nalgebra::{Complex, DMatrix, DVector};
use std::f64::consts::TAU;

/// One mode of ẋ = A x.
#[derive(Debug, Clone, PartialEq)]
pub struct Mode {
    /// The eigenvalue (of the pair, the one with Im λ > 0).
    pub eigenvalue: Complex<f64>,
    /// The period of an oscillation, s, as a person watching the body sees it: 2π/|Im λ|, or
    /// for an oscillation measured in turning axes (see
    /// [`frequency_in_space`](Self::frequency_in_space)) 2π over the frequency in space.
    pub period_s: Option<f64>,
    /// 2π/|Im λ|, s, where that differs from [`period_s`](Self::period_s): the period in
    /// the turning axes the state's roll and pitch are measured in.
    pub period_in_turning_axes_s: Option<f64>,
    /// −Re λ/|λ|, for λ ≠ 0.
    pub damping_ratio: Option<f64>,
    /// ln 2/Re λ, s, for a mode that grows.
    pub time_to_double_s: Option<f64>,
    /// ln 2/(−Re λ), s, for a mode that decays.
    pub time_to_half_s: Option<f64>,
    /// The states that dominate its eigenvector.
    pub dominant: Vec<String>,
    /// What the family calls it, where it has a name.
    pub name: Option<&'static str>,
    /// For an oscillation of roll and pitch measured in axes that turn at the heading's rate
    /// (a top's Euler angles, whose heading ψ turns with the spin): the frequency seen in
    /// space, rad/s, that rate less the frequency seen in the turning axes, with the sense
    /// in which the tilt turns (from the eigenvector's roll and pitch).
    pub frequency_in_space: Option<f64>,
}

/// The verdict on the linear model at an equilibrium, each real part judged against
/// [`growth_tolerance`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stability {
    /// Every mode decays.
    Asymptotic,
    /// No mode grows, some neither grow nor decay to the tolerance (an undamped oscillation,
    /// a free body's drift at rest): the linear model cannot tell whether the motion is
    /// stable, which the terms it leaves out decide.
    Marginal,
    /// Some mode grows.
    Unstable,
}

impl Stability {
    /// The verdict in words.
    pub fn describe(self) -> &'static str {
        match self {
            Stability::Asymptotic => "stable: every mode decays",
            Stability::Marginal => {
                "marginal: no mode grows, some neither grow nor decay (the linear model cannot \
                 tell whether the motion is stable)"
            }
            Stability::Unstable => "UNSTABLE: a mode grows",
        }
    }

    /// The verdict in one word, as `summary.json`-style outputs give it.
    pub fn word(self) -> &'static str {
        match self {
            Stability::Asymptotic => "stable",
            Stability::Marginal => "marginal",
            Stability::Unstable => "unstable",
        }
    }

    /// Whether the motion is stable, where the linear model decides it: `Some(true)` when
    /// every mode decays, `Some(false)` when one grows, `None` when it is marginal.
    pub fn is_stable(self) -> Option<bool> {
        match self {
            Stability::Asymptotic => Some(true),
            Stability::Marginal => None,
            Stability::Unstable => Some(false),
        }
    }
}

/// A real part counts as zero below `GROWTH_TOLERANCE` times ‖A‖₂ ([`growth_tolerance`]).
///
/// Why ‖A‖ and not the eigenvalues' size: the Schur form is backward stable, its eigenvalues
/// exact for some A + E with ‖E‖ ~ ε‖A‖, and a defective eigenvalue (a Jordan block of size
/// k, as a free body at rest has wherever an angle reads a rate) moves by (ε‖A‖)^(1/k)
/// ‖A‖^(1 − 1/k): about 1.5·10⁻⁸ ‖A‖ for k = 2. A nilpotent A (every eigenvalue zero,
/// computed as ±10⁻¹⁶) has a spectral radius of round-off, so a tolerance scaled to it calls
/// round-off growth; scaled to ‖A‖ it does not. 10⁻⁷ leaves a factor of seven above the
/// double eigenvalue's movement, while the weakest instability a scene means (10⁻³ of its
/// fastest mode and more) is seen.
pub const GROWTH_TOLERANCE: f64 = 1e-7;

/// The size below which a real part counts as zero: [`GROWTH_TOLERANCE`] times the largest
/// singular value of `a` (1/s). Zero for a zero matrix, whose eigenvalues are exactly zero.
pub fn growth_tolerance(a: &DMatrix<f64>) -> f64 {
    if a.is_empty() || a.iter().all(|v| *v == 0.0) {
        return 0.0;
    }
    let norm = a
        .clone()
        .try_svd(false, false, f64::EPSILON, 10_000)
        .map(|svd| svd.singular_values.max())
        // Should the SVD not converge, the Frobenius norm bounds the 2-norm from above.
        .unwrap_or_else(|| a.norm());
    GROWTH_TOLERANCE * norm
}

/// Whose names a mode is given: a catalog family's, or the planes of motion a vehicle's
/// designer reads (surge, sway and yaw, heave and pitch, roll).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Naming {
    /// The family's names.
    Family(Family),
    /// The planes of motion of a body moving in six degrees of freedom.
    Planes,
    /// The modes as flight-dynamics texts name them, for a state in wind axes (`vt`,
    /// `alpha`, `beta`, the Euler angles, `p`, `q`, `r`, `altitude`, `power`): the short
    /// period and the phugoid, the Dutch roll, the roll subsidence and the spiral, the power
    /// lag and the height mode.
    Flight,
}

/// The eigenvalues of `a`, sorted (largest real part first, then by imaginary part), its
/// modes and the verdict; `names` names the states of `a`, `naming` whose names the modes get and
/// `heading_rate` the rate at which the axes of its roll and pitch turn (zero where they do
/// not).
pub fn modes(
    a: &DMatrix<f64>,
    names: &[String],
    naming: Naming,
    heading_rate: f64,
) -> (Vec<Complex<f64>>, Vec<Mode>, Stability) {
    let mut eigenvalues = eigenvalues(a);
    eigenvalues.sort_by(|x, y| y.re.total_cmp(&x.re).then(y.im.total_cmp(&x.im)));
    let radius = eigenvalues.iter().fold(0.0f64, |m, l| m.max(l.norm()));
    let tolerance = growth_tolerance(a);
    let mut modes: Vec<Mode> = eigenvalues
        .iter()
        .filter(|l| l.im >= 0.0)
        .map(|&l| mode(a, l, (tolerance, radius), names, heading_rate))
        .collect();
    match naming {
        Naming::Family(family) => name_modes(&mut modes, family),
        Naming::Planes => {
            for mode in &mut modes {
                mode.name = plane_of_motion(mode);
            }
        }
        Naming::Flight => name_flight_modes(&mut modes, a, names, radius),
    }
    let stability = if eigenvalues.iter().any(|l| l.re > tolerance) {
        Stability::Unstable
    } else if eigenvalues.iter().all(|l| l.re < -tolerance) {
        Stability::Asymptotic
    } else {
        Stability::Marginal
    };
    (eigenvalues, modes, stability)
}

/// The most QR sweeps the Schur form may take before the matrix is turned and tried again.
const SCHUR_ITERATIONS: usize = 10_000;

/// The eigenvalues of `a` by the real Schur form. nalgebra's Francis steps can stall on a
/// matrix of exact zeros and symmetric blocks (a sleeping top's A), where its own
/// `complex_eigenvalues` would loop for ever; then the eigenvalues are those of Q A Qᵀ, with
/// Q a fixed orthogonal matrix (the Q of a QR factorisation of a fixed matrix), which are
/// the same to rounding and have no such structure.
pub fn eigenvalues(a: &DMatrix<f64>) -> Vec<Complex<f64>> {
    let schur = |m: DMatrix<f64>| {
        nalgebra::linalg::Schur::try_new(m, f64::EPSILON, SCHUR_ITERATIONS)
            .map(|s| s.complex_eigenvalues().iter().copied().collect::<Vec<_>>())
    };
    if let Some(found) = schur(a.clone()) {
        return found;
    }
    let n = a.nrows();
    let q = DMatrix::from_fn(n, n, |i, j| ((i * 7 + j * 3 + 1) as f64).sin())
        .qr()
        .q();
    let turned = &q * a * q.transpose();
    schur(turned).unwrap_or_else(|| vec![Complex::new(f64::NAN, f64::NAN); n])
}

/// One mode; a real part within `tolerance` of zero counts as zero (no doubling or halving
/// time, no damping), as the verdict counts it; `radius` is A's spectral radius, which sets
/// the shift of the inverse iteration.
fn mode(
    a: &DMatrix<f64>,
    eigenvalue: Complex<f64>,
    (tolerance, radius): (f64, f64),
    names: &[String],
    heading_rate: f64,
) -> Mode {
    let im = if eigenvalue.im.abs() <= tolerance {
        0.0
    } else {
        eigenvalue.im
    };
    let re = if eigenvalue.re.abs() <= tolerance {
        0.0
    } else {
        eigenvalue.re
    };
    let size = Complex::new(re, im).norm();
    let ln2 = std::f64::consts::LN_2;
    let vector = eigenvector(a, eigenvalue, radius);
    let largest = vector.iter().fold(0.0f64, |m, v| m.max(v.norm()));
    let dominant = vector
        .iter()
        .zip(names)
        .filter(|(v, _)| largest > 0.0 && v.norm() >= 0.5 * largest)
        .map(|(_, name)| name.clone())
        .collect();
    let in_space = frequency_in_space(&vector, names, im, heading_rate);
    let period = |frequency: f64| (frequency.abs() > tolerance).then(|| TAU / frequency.abs());
    Mode {
        eigenvalue,
        period_s: match in_space {
            Some(frequency) => period(frequency),
            None => period(im),
        },
        period_in_turning_axes_s: in_space.and_then(|_| period(im)),
        // + 0.0: an undamped mode's ratio is 0, not −0.
        damping_ratio: (size > 0.0).then(|| -re / size + 0.0),
        time_to_double_s: (re > 0.0).then(|| ln2 / re),
        time_to_half_s: (re < 0.0).then(|| ln2 / -re),
        frequency_in_space: in_space,
        dominant,
        name: None,
    }
}

/// See [`Mode::frequency_in_space`]: `None` without a turning frame, an oscillation, or roll
/// and pitch in the state.
fn frequency_in_space(
    vector: &DVector<Complex<f64>>,
    names: &[String],
    im: f64,
    heading_rate: f64,
) -> Option<f64> {
    let entry = |name: &str| names.iter().position(|n| n == name).map(|i| vector[i]);
    let (roll, pitch) = (entry("phi")?, entry("pitch").or_else(|| entry("theta"))?);
    if heading_rate == 0.0 || im <= 0.0 {
        return None;
    }
    let sense = (roll.conj() * pitch).im.signum();
    Some(heading_rate - sense * im)
}

/// The eigenvector of `eigenvalue` by inverse iteration, of unit length.
pub fn eigenvector(
    a: &DMatrix<f64>,
    eigenvalue: Complex<f64>,
    radius: f64,
) -> DVector<Complex<f64>> {
    let n = a.nrows();
    let shift = eigenvalue + Complex::new(1e-10, 1e-10) * radius.max(f64::MIN_POSITIVE);
    let shifted = DMatrix::from_fn(n, n, |i, j| {
        Complex::new(a[(i, j)], 0.0)
            - if i == j {
                shift
            } else {
                Complex::new(0.0, 0.0)
            }
    });
    let lu = shifted.lu();
    let mut vector = DVector::from_element(n, Complex::new(1.0, 0.0));
    for _ in 0..3 {
        match lu.solve(&vector) {
            Some(next) if next.norm() > 0.0 && next.norm().is_finite() => {
                vector = next.unscale(next.norm());
            }
            _ => break,
        }
    }
    vector
}

/// A vehicle's mode by the plane of motion its dominant states lie in: surge (u), sway and yaw
/// (v, r, ψ), heave and pitch (w, q, θ), roll (p, φ); none where they span planes, or for a
/// state that neither grows nor decays.
fn plane_of_motion(mode: &Mode) -> Option<&'static str> {
    const PLANES: [(&str, &[&str]); 4] = [
        ("surge", &["u"]),
        ("sway and yaw", &["v", "r", "psi"]),
        ("heave and pitch", &["w", "q", "theta"]),
        ("roll", &["p", "phi"]),
    ];
    let moving = mode.damping_ratio.is_some();
    PLANES
        .iter()
        .find(|(_, states)| (mode.dominant.iter()).all(|d| states.contains(&d.as_str())))
        .filter(|_| moving && !mode.dominant.is_empty())
        .map(|(name, _)| *name)
}

/// The modes of a state in wind axes, as flight-dynamics texts name them, each classed by its
/// eigenvector: a mode of the engine's power (the only one with a power component, the power's
/// rate reading nothing else) is its lag; the others are lateral-directional where their
/// share of β, φ, p, r (rad, rad/s) exceeds their share of α, θ, q, longitudinal otherwise.
/// A lateral oscillation is the Dutch roll; of the real lateral modes the fastest is the roll
/// subsidence, the slowest the spiral. A longitudinal oscillation in which α moves as much as
/// θ (|α| ≥ 0.3 |θ|) is the short period; one at nearly constant α, trading speed and height,
/// the phugoid; a real longitudinal mode that is slow (|λ| below 0.01/s, hundreds of seconds)
/// and mostly of the altitude is the height mode (the air's density changing with it; its α
/// and θ move together, so it is told apart before α's share is asked); another with α moving
/// as θ does is the short period split into two real roots (an aircraft that is statically
/// unstable, or nearly), and the rest, at nearly constant α, the phugoid become real (at an
/// aft centre of gravity the phugoid's pair splits and one root may grow).
fn name_flight_modes(modes: &mut [Mode], a: &DMatrix<f64>, names: &[String], radius: f64) {
    let index = |name: &str| names.iter().position(|n| n == name);
    let share = |v: &DVector<Complex<f64>>, set: &[&str]| -> f64 {
        set.iter()
            .filter_map(|n| index(n))
            .map(|i| v[i].norm())
            .sum()
    };
    let entry = |v: &DVector<Complex<f64>>, name: &str| index(name).map_or(0.0, |i| v[i].norm());
    let mut lateral_real: Vec<usize> = Vec::new();
    for (i, mode) in modes.iter_mut().enumerate() {
        if mode.damping_ratio.is_none() {
            continue;
        }
        let v = eigenvector(a, mode.eigenvalue, radius);
        let oscillates = mode.eigenvalue.im > 0.0;
        let lateral = share(&v, &["beta", "phi", "p", "r"]);
        let longitudinal = share(&v, &["alpha", "theta", "q"]);
        let pitching = entry(&v, "alpha") >= 0.3 * entry(&v, "theta");
        let largest = v.iter().fold(0.0f64, |m, x| m.max(x.norm()));
        mode.name = if entry(&v, "power") > 1e-6 * largest {
            Some("power lag")
        } else if lateral > longitudinal {
            if oscillates {
                Some("Dutch roll")
            } else {
                lateral_real.push(i);
                None
            }
        } else if oscillates {
            Some(if pitching { "short period" } else { "phugoid" })
        } else if entry(&v, "altitude") == largest && mode.eigenvalue.norm() < 0.01 {
            Some("height")
        } else if pitching {
            Some("short period, aperiodic")
        } else {
            Some("phugoid, aperiodic")
        };
    }
    lateral_real.sort_by(|&i, &j| modes[i].eigenvalue.re.total_cmp(&modes[j].eigenvalue.re));
    if let (Some(&fastest), Some(&slowest)) = (lateral_real.first(), lateral_real.last()) {
        modes[fastest].name = Some("roll subsidence");
        if slowest != fastest {
            modes[slowest].name = Some("spiral");
        }
    }
}

/// Names the modes where the family knows them.
fn name_modes(modes: &mut [Mode], family: Family) {
    let is =
        |mode: &Mode, names: &[&str]| mode.dominant.iter().all(|d| names.contains(&d.as_str()));
    let mut top_oscillations: Vec<usize> = Vec::new();
    for (index, mode) in modes.iter_mut().enumerate() {
        let oscillates = mode.eigenvalue.im > 0.0;
        let moving = mode.damping_ratio.is_some();
        mode.name = match family {
            Family::Pendulum if moving => Some("the pendulum's swing"),
            Family::Spatial
                if oscillates
                    && is(mode, &["p", "phi"])
                    && mode.dominant.iter().any(|d| d == "p") =>
            {
                Some("roll")
            }
            Family::Spatial if is(mode, &["p", "q", "r"]) && moving => Some(if oscillates {
                "nutation"
            } else {
                "the spin's instability"
            }),
            Family::Top if oscillates => {
                top_oscillations.push(index);
                None
            }
            Family::Top if moving => Some("the top's fall"),
            // Surge among the dominant entries: where u̇ depends on u alone (a straight course),
            // the sway–yaw modes have no u at all, and the surge mode drags some sway along.
            Family::PlanarAtG | Family::PlanarMidship
                if moving && mode.dominant.iter().any(|d| d == "u") =>
            {
                Some("surge")
            }
            Family::PlanarAtG | Family::PlanarMidship if moving => Some("sway and yaw"),
            _ => None,
        };
    }
    // A sleeping top's two oscillations: the faster in space is its nutation, the slower its
    // precession.
    let in_space = |mode: &Mode| mode.frequency_in_space.unwrap_or(mode.eigenvalue.im).abs();
    top_oscillations.sort_by(|&i, &j| in_space(&modes[j]).total_cmp(&in_space(&modes[i])));
    for (rank, index) in top_oscillations.into_iter().enumerate() {
        modes[index].name = Some(if rank == 0 { "nutation" } else { "precession" });
    }
}
