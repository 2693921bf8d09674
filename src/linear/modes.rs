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
//! half the largest, and a name ([`super::naming`]).
//!
//! **What moves is read in comparable units.** An eigenvector's entries are in the state's
//! units, and compared raw a length in feet outweighs an angle in radians whatever moves: every
//! longitudinal mode of an aircraft would be "altitude". So each entry is read as the plant
//! says ([`Reading`]) before the shares are compared: an angle as it is, in radians; a rate
//! (rad/s) times the mode's own time 1/|λ|, so that it counts as the angle it turns through in
//! that time (q/|λ| is θ's swing wherever θ̇ = q, so a rate never outweighs its angle by its
//! units alone, in a fast mode or a slow one); a velocity over the speed at the point (u/U, an
//! angle of attack w/U); a length over the plant's length scale (an aircraft's altitude over
//! V²/g: where speed is traded for height, g Δh = −V ΔV, so Δh/(V²/g) = −ΔV/V and the two are
//! the same size; a ship's or a vehicle's position over its length); a power over full power. A mode that neither grows
//! nor decays has no time of its own: its rates are zero where its angles hold still, and are
//! read as zero.

use super::naming;
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
    /// Each state entry's share of the eigenvector, read as [`Reading`] says and divided by
    /// the largest (so the largest is 1), in the order of the state's names.
    pub shares: Vec<f64>,
    /// The states that dominate its eigenvector: those whose share is at least half the
    /// largest.
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

/// Whose names a mode is given: a catalog family's, the planes of motion a vehicle's or a
/// ship's designer reads (surge, sway and yaw, heave and pitch, roll), or a flight text's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Naming {
    /// The family's names.
    Family(Family),
    /// The planes of motion of a body moving in six degrees of freedom (a vehicle's), or in
    /// three (a ship's surge, sway and yaw): each mode by the plane it moves, or two coupled.
    Planes,
    /// The modes as flight-dynamics texts name them, for a state in wind axes (`vt`,
    /// `alpha`, `beta`, the Euler angles, `p`, `q`, `r`, `altitude`, `power`): the short
    /// period and the phugoid, the Dutch roll, the roll subsidence and the spiral, the power
    /// lag and the height mode.
    Flight,
}

/// How one entry of an eigenvector is read when the entries are compared (see the module
/// docs): what makes a share of the eigenvector the same size in any unit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Reading {
    /// As it is: an angle in radians, or an entry of a model that gives no scale (a catalog
    /// body's).
    AsIs,
    /// A rate, rad/s: times the mode's own time 1/|λ|, the angle it turns through in it.
    Rate,
    /// Divided by this size of its unit: a velocity by the speed at the point, a length by
    /// the plant's length scale, a power by full power.
    Over(f64),
}

impl Reading {
    /// An entry in `unit` read against `speed` (a velocity's unit, `m/s` or `ft/s`) and
    /// `length` (a length's, `m` or `ft`): an angle as it is, a rate by the mode's time, a
    /// velocity over `speed`, a length over `length`, a percentage over 100; any other unit
    /// as it is. A speed or a length that is not positive and finite reads its entries as they
    /// are.
    pub fn by_unit(unit: &str, speed: f64, length: f64) -> Reading {
        let over = |size: f64| {
            if size > 0.0 && size.is_finite() {
                Reading::Over(size)
            } else {
                Reading::AsIs
            }
        };
        match unit {
            "rad/s" => Reading::Rate,
            "m/s" | "ft/s" => over(speed),
            "m" | "ft" => over(length),
            "percent" => Reading::Over(100.0),
            _ => Reading::AsIs,
        }
    }

    /// The size of `entry` so read, in a mode whose eigenvalue has magnitude `size` (zero for
    /// a mode that neither grows nor decays, whose rates are read as zero).
    fn read(self, entry: f64, size: f64) -> f64 {
        match self {
            Reading::AsIs => entry,
            Reading::Rate if size > 0.0 => entry / size,
            Reading::Rate => 0.0,
            Reading::Over(scale) => entry / scale,
        }
    }
}

/// The eigenvalues of `a`, sorted (largest real part first, then by imaginary part), its
/// modes and the verdict; `names` names the states of `a`, `readings` says how each entry of
/// an eigenvector is read when they are compared (none: each as it is), `naming` whose names
/// the modes get and `heading_rate` the rate at which the axes of its roll and pitch turn
/// (zero where they do not).
pub fn modes(
    a: &DMatrix<f64>,
    (names, readings): (&[String], &[Reading]),
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
        .map(|&l| mode(a, l, (tolerance, radius), (names, readings), heading_rate))
        .collect();
    match naming {
        Naming::Family(family) => naming::name_modes(&mut modes, family),
        Naming::Planes => naming::name_planes(&mut modes, names),
        Naming::Flight => naming::name_flight_modes(&mut modes, names),
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
    (names, readings): (&[String], &[Reading]),
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
    let shares = shares(&vector, readings, size);
    let dominant = (shares.iter().zip(names))
        .filter(|(share, _)| **share >= 0.5)
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
        shares,
        dominant,
        name: None,
    }
}

/// Each entry's size in `vector` read as `readings` say (each as it is where they are
/// missing), in a mode whose eigenvalue has magnitude `size`, over the largest: all zero for a
/// zero vector.
fn shares(vector: &DVector<Complex<f64>>, readings: &[Reading], size: f64) -> Vec<f64> {
    let read: Vec<f64> = (vector.iter().enumerate())
        .map(|(i, v)| {
            let reading = readings.get(i).copied().unwrap_or(Reading::AsIs);
            reading.read(v.norm(), size).abs()
        })
        .collect();
    let largest = read.iter().fold(0.0f64, |m, v| m.max(*v));
    if largest > 0.0 && largest.is_finite() {
        read.iter().map(|v| v / largest).collect()
    } else {
        vec![0.0; read.len()]
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A pitch oscillation θ̈ = −16 θ − 0.8 θ̇ on (θ, q): q = λ θ, so read by the mode's time
    /// q/|λ| is θ's swing, the same share; read as it is, q in rad/s outweighs θ four times
    /// (|λ| = 4/s), and θ is not among the dominant states.
    #[test]
    fn a_rate_read_by_the_modes_time_is_the_angle_it_swings() {
        let a = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, -16.0, -0.8]);
        let names = ["theta".to_owned(), "q".to_owned()];
        let read = [Reading::AsIs, Reading::Rate];
        let (_, scaled, _) = modes(&a, (&names, &read), Naming::Planes, 0.0);
        let (_, raw, _) = modes(&a, (&names, &[]), Naming::Planes, 0.0);
        let [theta, q] = [scaled[0].shares[0], scaled[0].shares[1]];
        assert!(
            (theta - 1.0).abs() < 1e-12 && (q - 1.0).abs() < 1e-12,
            "{theta} {q}"
        );
        assert_eq!(scaled[0].dominant, ["theta", "q"]);
        assert!(
            (raw[0].shares[0] - 0.25).abs() < 1e-12,
            "{:?}",
            raw[0].shares
        );
        assert_eq!(raw[0].dominant, ["q"]);
    }

    /// A velocity over the speed, a length over the length, a rate by the mode's time, a
    /// percentage over 100, an angle and an unknown unit as they are; no scale, as they are.
    #[test]
    fn each_unit_is_read_against_its_scale() {
        assert_eq!(
            Reading::by_unit("ft/s", 500.0, 7800.0),
            Reading::Over(500.0)
        );
        assert_eq!(Reading::by_unit("m", 2.0, 160.0), Reading::Over(160.0));
        assert_eq!(Reading::by_unit("rad/s", 2.0, 160.0), Reading::Rate);
        assert_eq!(
            Reading::by_unit("percent", 2.0, 160.0),
            Reading::Over(100.0)
        );
        assert_eq!(Reading::by_unit("rad", 2.0, 160.0), Reading::AsIs);
        assert_eq!(Reading::by_unit("m/s", 0.0, 160.0), Reading::AsIs);
        assert_eq!(Reading::Rate.read(3.0, 0.0), 0.0, "a neutral mode's rate");
        assert_eq!(Reading::Rate.read(3.0, 2.0), 1.5);
    }
}
