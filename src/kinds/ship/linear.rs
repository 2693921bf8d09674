//! The linear model about the straight course: the sway–yaw equations at the design speed U₀,
//! M ν̇ + N ν = b δ with ν = (v, r), the Nomoto models, the course-stability criterion and
//! the pivot point.
//!
//! With the mass matrix M (4.46's, with the added mass), N = [[−Y_v, M U₀ − Y_r],
//! [−N_v, M x_G U₀ − N_r]] (the rigid-body terms M u r and M x_G u r of 4.46 at u = U₀; a
//! folded table has them in its Y_r and N_r already) and b = (Y_δ, N_δ), the yaw-rate
//! response is
//!
//! ```text
//! r/δ = K (1 + T₃ s) / ((1 + T₁ s)(1 + T₂ s)),   T₁T₂ = det M / det N,
//! T₁ + T₂ = (n₁₁m₂₂ + n₂₂m₁₁ − n₁₂m₂₁ − n₂₁m₁₂) / det N,
//! K = (n₁₁b₂ − n₂₁b₁) / det N,   K T₃ = (m₁₁b₂ − m₂₁b₁) / det N,
//! ```
//!
//! (Nomoto's second-order model; the first-order one is K and T = T₁ + T₂ − T₃). The straight
//! course is stable when det N > 0: in the prime system det N = (½ρ)²L⁶U₀² C′ with the
//! textbook's C′ = Y′_v(N′_r − m′x′_G) − (Y′_r − m′)N′_v. In a steady turn the point of the
//! centre line that moves straight ahead, v + x_p r = 0, is the pivot point x_p = −v/r.
//!
//! [`linearise`] takes the same matrices from the running model instead: its Jacobian, the
//! program derived from the proved system's exact derivative and proved equal to it. The two
//! agree (tests/ship.rs). And [`linearise_ship`] hands the ship to the linearisation of every
//! scene ([`crate::linear`]): the states set aside, A and B on (u, v, r), the modes and the
//! verdict, whose sway–yaw eigenvalues are −1/T₁ and −1/T₂.

use super::mmg::{Edge, MmgShip};
use super::model::{STATE, ShipModel};
use super::table::ShipTable;
use super::{Force, Term, Units};
use crate::linear::{Evaluation, LinearError, LinearPlant, Linearisation, Naming, Reading};
use crate::models::{Family, Model};
use nalgebra::DMatrix;
use std::collections::BTreeMap;

/// Nomoto's models of the yaw-rate response to the rudder.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Nomoto {
    /// The gain K, 1/s (r per radian of rudder in the steady turn).
    pub k: f64,
    /// T₁, s: the time constant of larger magnitude (negative for a course-unstable ship).
    pub t1: f64,
    /// T₂, s.
    pub t2: f64,
    /// T₃, s: the lead.
    pub t3: f64,
    /// The first-order model's T = T₁ + T₂ − T₃, s.
    pub t: f64,
}

impl Nomoto {
    /// From the sum and product of T₁ and T₂, K and K T₃; `None` where T₁, T₂ are not real.
    fn from_sums(sum: f64, product: f64, k: f64, k_t3: f64) -> Option<Self> {
        let discriminant = sum * sum - 4.0 * product;
        if discriminant < 0.0 {
            return None;
        }
        // The root of larger magnitude without cancellation, the other from the product.
        let large = 0.5 * (sum + sum.signum() * discriminant.sqrt());
        let small = product / large;
        let t3 = k_t3 / k;
        Some(Nomoto {
            k,
            t1: large,
            t2: small,
            t3,
            t: large + small - t3,
        })
    }

    /// From the state-space form ν̇ = A ν + B δ: r/δ = (B₂ s + A₂₁B₁ − A₁₁B₂)/(s² − tr A s
    /// + det A).
    pub fn from_state_space(a: [[f64; 2]; 2], b: [f64; 2]) -> Option<Self> {
        let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
        let trace = a[0][0] + a[1][1];
        let k = (a[1][0] * b[0] - a[0][0] * b[1]) / det;
        Self::from_sums(-trace / det, 1.0 / det, k, b[1] / det)
    }
}

/// The sway–yaw equations about the straight course at U₀, in SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearModel {
    /// M: the sway–yaw block of the mass matrix.
    pub mass: [[f64; 2]; 2],
    /// N.
    pub damping: [[f64; 2]; 2],
    /// b = (Y_δ, N_δ).
    pub rudder: [f64; 2],
    /// U₀, m/s.
    pub speed: f64,
    /// (½ρ)²L⁶U₀², where the table is in the prime system: det N over it is C′.
    prime_scale: Option<f64>,
}

/// ∂F/∂v, ∂F/∂r, ∂F/∂δ of one load at the straight course (u = U₀, v = r = δ = 0), in SI.
fn derivatives(table: &ShipTable, terms: &BTreeMap<Term, f64>, force: Force) -> [f64; 3] {
    let moment = i32::from(force == Force::N);
    let mut out = [0.0; 3];
    for (term, value) in terms.iter().filter(|(t, _)| t.force == force) {
        let [a, b, c, d, e] = term.powers;
        if let (Some(p), [0, 0, 0, 0, 1]) = (&table.propulsion, term.powers) {
            // ½ρL²c² Y′_e e with e = δ − (v + x_R r)/c, about c = c₀: (c₀², −c₀, −c₀ x_R).
            let (inflow, scale) = (p.approach_inflow, table.si_scale(2 + moment));
            let position = p.rudder_position * table.si_scale(1);
            out[0] -= value * scale * inflow;
            out[1] -= value * scale * inflow * position;
            out[2] += value * scale * inflow * inflow;
            continue;
        }
        let slot = match (b, c, d, e) {
            (1, 0, 0, 0) => 0,
            (0, 1, 0, 0) => 1,
            (0, 0, 1, 0) => 2,
            _ => continue,
        };
        let u0 = table.design_speed;
        out[slot] += value
            * match table.units {
                Units::Dimensional => u0.powi(i32::from(a)),
                // u′ = 0 on the design speed; the term is ½ρL^(2+c)U^(2−b−c) v^b r^c δ^d.
                Units::Prime if a > 0 => 0.0,
                // With propulsion the rudder is on its inflow speed, c₀ at the approach, where
                // the change of its share of Y_v and Y_r with c vanishes.
                Units::Prime if d > 0 && table.propulsion.is_some() => {
                    let inflow = table.propulsion.map_or(f64::NAN, |p| p.approach_inflow);
                    table.si_scale(2 + moment) * inflow * inflow
                }
                Units::Prime => {
                    let c = i32::from(c);
                    table.si_scale(2 + c + moment) * u0.powi(2 - i32::from(b) - c)
                }
            };
    }
    out
}

impl LinearModel {
    /// The closed form from the table's linear derivatives (rigid-body terms separate); an
    /// MMG ship's from [`LinearModel::mmg`].
    pub fn closed_form(table: &ShipTable) -> Self {
        match &table.mmg {
            Some(mmg) => Self::mmg(table, mmg, Edge::TowardPositive),
            None => Self::from_terms(table, &table.terms, true),
        }
    }

    /// An MMG ship's: the hull's linear derivatives at U₀ (½ρLdU₀ Y′_v, ½ρL²dU₀ Y′_r,
    /// ½ρL²dU₀ N′_v, ½ρL³dU₀ N′_r), the rudder's derivatives by v, r and δ at the straight
    /// course with the propeller at n₀, and the rigid and added masses' (M + m_x)U₀ and
    /// M x_G U₀ in r. The rudder's flow straightening changes at β_R = 0 (γ_R⁺ for β_R ≥ 0,
    /// γ_R⁻ below) and the wake at β_P = 0, so the straight course has two one-sided linear
    /// models: [`Edge::TowardPositive`] gives the one toward β_R > 0, the paper's γ_R⁺ and
    /// C₂⁺, which a small turn to starboard (r > 0, the midship drifting to port) sees;
    /// [`Edge::TowardNegative`] the other, a turn to port's. The course-stability index C′ is
    /// det N over (½ρ)²L⁶U₀², the prime system's.
    pub fn mmg(table: &ShipTable, mmg: &MmgShip, edge: Edge) -> Self {
        let m = table.mass_matrix();
        let ship = &mmg.parameters.particulars;
        let hull = &mmg.parameters.hull;
        let u0 = table.design_speed;
        let (rho, l, d) = (ship.density, ship.length, ship.draft);
        let q = 0.5 * rho * l * d * u0;
        let rudder = mmg
            .loads_with_derivatives_toward([u0, 0.0, 0.0, 0.0, mmg.approach_rate], edge)
            .map_or([[f64::NAN; 5]; 3], |a| a.by);
        let y_v = q * hull.y_v + rudder[1][1];
        let y_r = q * l * hull.y_r + rudder[1][2];
        let n_v = q * l * hull.n_v + rudder[2][1];
        let n_r = q * l * l * hull.n_r + rudder[2][2];
        let surge_mass = m[0][0];
        let (mass, x_g) = (table.body.mass, table.body.x_g);
        LinearModel {
            mass: [[m[1][1], m[1][2]], [m[2][1], m[2][2]]],
            damping: [[-y_v, surge_mass * u0 - y_r], [-n_v, mass * x_g * u0 - n_r]],
            rudder: [rudder[1][3], rudder[2][3]],
            speed: u0,
            prime_scale: Some((0.5 * rho).powi(2) * l.powi(6) * u0 * u0),
        }
    }

    /// The closed form from a table's terms; `add_rigid_body` for terms without the
    /// rigid-body parts (false for a folded table, whose Y_r and N_r hold them).
    pub fn from_terms(
        table: &ShipTable,
        terms: &BTreeMap<Term, f64>,
        add_rigid_body: bool,
    ) -> Self {
        let m = table.mass_matrix();
        let [y_v, y_r, y_d] = derivatives(table, terms, Force::Y);
        let [n_v, n_r, n_d] = derivatives(table, terms, Force::N);
        let (mass, x_g) = (
            table.body.mass * table.si_scale(3),
            table.body.x_g * table.si_scale(1),
        );
        let u0 = table.design_speed;
        let (rigid_y, rigid_n) = if add_rigid_body {
            (mass * u0, mass * x_g * u0)
        } else {
            (0.0, 0.0)
        };
        let prime_scale = match table.units {
            Units::Prime => table
                .density
                .zip(table.length)
                .map(|(rho, l)| (0.5 * rho).powi(2) * l.powi(6) * u0 * u0),
            Units::Dimensional => None,
        };
        LinearModel {
            mass: [[m[1][1], m[1][2]], [m[2][1], m[2][2]]],
            damping: [[-y_v, rigid_y - y_r], [-n_v, rigid_n - n_r]],
            rudder: [y_d, n_d],
            speed: u0,
            prime_scale,
        }
    }

    /// det N: the straight course is stable where it is positive (with det M > 0).
    pub fn det_damping(&self) -> f64 {
        let n = self.damping;
        n[0][0] * n[1][1] - n[0][1] * n[1][0]
    }

    /// C′ = Y′_v(N′_r − m′x′_G) − (Y′_r − m′)N′_v, for a table in the prime system.
    pub fn stability_index(&self) -> Option<f64> {
        self.prime_scale.map(|scale| self.det_damping() / scale)
    }

    /// Whether the straight course is stable.
    pub fn course_stable(&self) -> bool {
        self.det_damping() > 0.0
    }

    /// ν̇ = A ν + B δ: A = −M⁻¹N, B = M⁻¹b.
    pub fn state_space(&self) -> ([[f64; 2]; 2], [f64; 2]) {
        let m = self.mass;
        let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
        let inverse = [
            [m[1][1] / det, -m[0][1] / det],
            [-m[1][0] / det, m[0][0] / det],
        ];
        let times = |row: [f64; 2], col: [f64; 2]| row[0] * col[0] + row[1] * col[1];
        let n_col = |j: usize| [self.damping[0][j], self.damping[1][j]];
        let a = std::array::from_fn(|i| std::array::from_fn(|j| -times(inverse[i], n_col(j))));
        let b = std::array::from_fn(|i| times(inverse[i], self.rudder));
        (a, b)
    }

    /// Nomoto's models by the closed form of the module docs; `None` where T₁, T₂ are not real.
    pub fn nomoto(&self) -> Option<Nomoto> {
        let (m, n, b) = (self.mass, self.damping, self.rudder);
        let det_m = m[0][0] * m[1][1] - m[0][1] * m[1][0];
        let det_n = self.det_damping();
        let sum =
            (n[0][0] * m[1][1] + n[1][1] * m[0][0] - n[0][1] * m[1][0] - n[1][0] * m[0][1]) / det_n;
        let k = (n[0][0] * b[1] - n[1][0] * b[0]) / det_n;
        let k_t3 = (m[0][0] * b[1] - m[1][0] * b[0]) / det_n;
        Nomoto::from_sums(sum, det_m / det_n, k, k_t3)
    }

    /// The slowest time constant of the sway–yaw modes, s: 1/min |Re λ| over the eigenvalues
    /// λ of A (|T₁| of Nomoto's model where T₁ and T₂ are real; the decay of the pair's
    /// envelope where they are not); infinite for a mode that neither grows nor decays.
    pub fn slowest_time_constant(&self) -> f64 {
        let (a, _) = self.state_space();
        let trace = a[0][0] + a[1][1];
        let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
        let discriminant = 0.25 * trace * trace - det;
        let slowest = if discriminant < 0.0 {
            (0.5 * trace).abs()
        } else {
            // The root of larger magnitude without cancellation, the other from the product.
            let large = 0.5 * trace + trace.signum() * discriminant.sqrt();
            (det / large).abs().min(large.abs())
        };
        1.0 / slowest
    }

    /// The pivot point x_p = −v/r of the steady turn, m ahead of midship.
    pub fn pivot_point(&self) -> f64 {
        let (n, b) = (self.damping, self.rudder);
        // ν = N⁻¹ b δ; the common 1/det N cancels in the ratio.
        let v = n[1][1] * b[0] - n[0][1] * b[1];
        let r = -n[1][0] * b[0] + n[0][0] * b[1];
        -v / r
    }
}

/// A and B of ν̇ = A ν + B δ taken from the running model about the straight course at
/// `speed`: its proved Jacobian program there (∂(v̇, ṙ)/∂(v, r) and ∂(v̇, ṙ)/∂δ).
pub fn linearise(model: &ShipModel, speed: f64) -> ([[f64; 2]; 2], [f64; 2]) {
    let mut state = [0.0; 7];
    state[0] = speed;
    let jacobian = model.state_jacobian(&state, &[0.0, model.approach_rate(), 0.0]);
    let row = |i: usize| [jacobian[i][1], jacobian[i][2]];
    ([row(1), row(2)], [jacobian[1][6], jacobian[2][6]])
}

/// The ship as the linearisation of every scene reads it ([`crate::linear::LinearPlant`]):
/// the state (u, v, r, X, Y, ψ) and the rudder angle δ as its control input, held where it is
/// put (the steering gear's lag and limits left out, as Nomoto's models leave them); A and B
/// from the running model's proved Jacobian, ∂f/∂(u, v, r, X, Y, ψ) and ∂f/∂δ.
#[derive(Debug, Clone, Copy)]
pub struct ShipPlant<'a> {
    /// The ship.
    pub model: &'a ShipModel,
    /// Its length L, m: what a position is read against when the modes compare what moves.
    pub length: f64,
}

impl ShipPlant<'_> {
    /// The model's state with the rudder at `delta`.
    fn full(state: &[f64], delta: f64) -> [f64; 7] {
        std::array::from_fn(|i| if i < 6 { state[i] } else { delta })
    }
}

impl LinearPlant for ShipPlant<'_> {
    fn name(&self) -> &'static str {
        <ShipModel as Model<f64, 7, 3>>::NAME
    }

    /// The ship is a planar body about midship.
    fn family(&self) -> Family {
        Family::PlanarMidship
    }

    /// By the planes of motion its modes move (surge; sway and yaw), read in comparable units.
    fn naming(&self) -> Naming {
        Naming::Planes
    }

    /// A velocity over the speed at the point, the yaw rate by the mode's time, a position
    /// over L, the heading as it is.
    fn readings(&self, state: &[f64]) -> Vec<Reading> {
        let speed = state[0].hypot(state[1]);
        (STATE[..6].iter())
            .map(|name| {
                let unit = crate::models::state_unit(name).unwrap_or("");
                Reading::by_unit(unit, speed, self.length)
            })
            .collect()
    }

    fn state_names(&self) -> Vec<&'static str> {
        STATE[..6].to_vec()
    }

    fn input_names(&self) -> Vec<&'static str> {
        vec!["delta"]
    }

    fn aliases(&self) -> &'static [(&'static str, &'static str)] {
        &ALIASES
    }

    fn inputs(&self, _state: &[f64], extra: &[f64]) -> Vec<f64> {
        extra.to_vec()
    }

    fn evaluate(&self, state: &[f64], extra: &[f64]) -> Result<Evaluation, LinearError> {
        let full = Self::full(state, extra[0]);
        let input = [0.0, self.model.approach_rate(), 0.0];
        let rates = self.model.rhs(&full, &input);
        let jacobian = self.model.state_jacobian(&full, &input);
        let a = DMatrix::from_fn(6, 6, |i, j| jacobian[i][j]);
        let b = DMatrix::from_fn(6, 1, |i, _| jacobian[i][6]);
        let rates = rates[..6].to_vec();
        if !(rates.iter().chain(a.iter()).chain(b.iter())).all(|v| v.is_finite()) {
            return Err(LinearError::NotFinite(format!("the ship at {full:?}")));
        }
        Ok(Evaluation { rates, a, b })
    }

    /// The model's pattern on (u, v, r, X, Y, ψ); the accelerations depend on ψ only in a
    /// wind.
    fn pattern(&self) -> Vec<(usize, usize)> {
        let pattern = <ShipModel as Model<f64, 7, 3>>::STATE_JACOBIAN;
        let windage = self.model.wind().is_some();
        (pattern.iter().copied())
            .filter(|&(i, j)| i < 6 && j < 6)
            .filter(|&(i, j)| windage || i >= 3 || j != 5)
            .collect()
    }

    fn jacobians(&self) -> &'static str {
        "proved: the table's Jacobian program, derived and proved equal to the exact \
         derivative of its equations when the scene was read"
    }
}

/// The rudder angle, as a `[linear]` table may also call it.
pub(crate) const ALIASES: [(&str, &str); 1] = [("rudder", "delta")];

/// The ship linearised by the linearisation of every scene about the point its `[linear]`
/// table names, by default its approach (straight ahead at U₀, the rudder amidships): the
/// states set aside (the position and the heading), A and B on (u, v, r), the modes (surge;
/// sway and yaw, at −1/T₁ and −1/T₂ of Nomoto's model about the approach) and the verdict. A
/// table with bias terms (the Mariner's Y₀, N₀) is not in equilibrium at the approach, and the
/// linearisation says by how much; `trim = ["rudder", "v", "u"]` finds the rudder angle, the
/// drift and the speed that hold it on a straight course.
pub fn linearise_ship(
    scene: &super::ShipScene,
    model: &ShipModel,
) -> Result<Linearisation, LinearError> {
    let plant = ShipPlant {
        model,
        length: scene.length,
    };
    let start = scene.start();
    let (mut state, mut extra) = (start[..6].to_vec(), vec![start[6]]);
    let names = (&STATE[..6], &STATE[6..], &ALIASES[..]);
    crate::linear::set_at(&scene.linear, names, (&mut state, &mut extra))?;
    crate::linear::linearise(&plant, (state, extra), &scene.linear)
}

/// Nomoto's models, the course stability and the pivot point, as text: the ship's own, in calm
/// air (a wind's loads turn with the heading, which Nomoto's model has not; the linearisation
/// above it keeps ψ).
pub fn nomoto_report(scene: &super::ShipScene, model: &ShipModel, linear: &LinearModel) -> String {
    let mut text = String::new();
    let speed = scene.table.design_speed;
    let air = match model.wind() {
        Some(_) => " in calm air",
        None => "",
    };
    line(
        &mut text,
        format!(
            "{}: the linear model about the straight course at U₀ = {speed} m/s{air}",
            crate::output::text::printable(&scene.title)
        ),
    );
    let show = |text: &mut String, what: &str, nomoto: Option<Nomoto>| {
        let said = match nomoto {
            Some(n) => format!(
                "  {what:<34} K = {:.6e} 1/s, T₁ = {:.6} s, T₂ = {:.6} s, T₃ = {:.6} s, T = {:.6} s",
                n.k, n.t1, n.t2, n.t3, n.t
            ),
            None => format!("  {what:<34} T₁ and T₂ are not real: no Nomoto form"),
        };
        line(text, said);
    };
    show(&mut text, "Nomoto, closed form:", linear.nomoto());
    let (a, b) = linearise(&model.calm(), speed);
    show(
        &mut text,
        "Nomoto, linearised model:",
        Nomoto::from_state_space(a, b),
    );
    if let Some(d) =
        super::summary::nomoto_difference(linear.nomoto(), Nomoto::from_state_space(a, b))
    {
        line(
            &mut text,
            format!("  {:<34} {d:.1e}", "largest relative difference:"),
        );
    }
    let verdict = if linear.course_stable() {
        "stable"
    } else {
        "UNSTABLE"
    };
    let stability = match linear.stability_index() {
        Some(c) => format!(
            "  course stability: C′ = Y′v(N′r − m′x′G) − (Y′r − m′)N′v = {c:.6e}: {verdict}"
        ),
        None => format!(
            "  course stability: det N = {:.6e} (SI): {verdict}",
            linear.det_damping()
        ),
    };
    line(&mut text, stability);
    let pivot = linear.pivot_point();
    line(
        &mut text,
        format!(
            "  pivot point: x_p = {pivot:.2} m ahead of midship ({:.3} L)",
            pivot / scene.length
        ),
    );
    if let Some(mmg) = &scene.table.mmg {
        let convention = super::summary::MMG_LINEAR_CONVENTION;
        line(
            &mut text,
            format!("  MMG: the linear model above is {convention}"),
        );
        let port = LinearModel::mmg(&scene.table, mmg, Edge::TowardNegative);
        show(&mut text, "Nomoto, toward port:", port.nomoto());
        let verdict = if port.course_stable() {
            "stable"
        } else {
            "UNSTABLE"
        };
        let index = port.stability_index().unwrap_or(f64::NAN);
        line(
            &mut text,
            format!("  course stability toward port: C′ = {index:.6e}: {verdict}"),
        );
        if port.course_stable() != linear.course_stable() {
            line(
                &mut text,
                "  the two sides disagree: the straight course is not stable (a small turn to \
                 the unstable side grows)"
                    .to_owned(),
            );
        }
    }
    text
}

/// Appends `content` and a newline.
fn line(text: &mut String, content: String) {
    text.push_str(&content);
    text.push('\n');
}
