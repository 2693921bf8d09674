//! A hydrodynamic table as a scene writes it: coefficient names, the unit system, the
//! rigid-body convention, and the conversion of a folded table.
//!
//! Names are read the way published tables and public codes write them: the load, then one
//! letter per power of u, v, r, δ (`d`) and the effective rudder angle e of a ship with a
//! propulsion model ([`super::propulsion`]), in any order (`Yvvr`, `Xrv`, `Yeee`), a `0` for a bias
//! term (`Y0`, and `Y0u`, which is the same monomial as `Yu`), `dot` for the added mass
//! (`Xudot`, `Yvdot`, `Yrdot`, `Nvdot`, `Nrdot`); an underscore after the load is allowed
//! (`Y_vvr`). Every value is kept exactly as written.
//!
//! **Folded tables.** Many published tables fold rigid-body terms of 4.46 into their
//! coefficients: the Mariner table of Chislett & Strøm-Tejsen gives X_vr = m′, X_rr with
//! m′x_G′ in it, Y_r and Y_ur as Y_r − m′ and Y_ur − m′, N_r and N_ur with −m′x_G′ in them.
//! `eom` writes those terms explicitly (4.46), so a folded table is converted: m′ (or M)
//! and m′x_G′ (or M x_G) are taken back out of those six coefficients. In the prime system
//! the folded form stands for −m′(u/U) r′ by −m′(1 + u′) r′, which is exact on the design
//! speed and on the straight course (U = U₀), where the linear model is taken, and differs
//! by m′r′(U − U₀)/U elsewhere: the run uses 4.46's exact M u r.

use super::ShipError;
use super::mmg::{MmgParameters, MmgShip};
use super::propulsion::Propulsion;
use super::wind::{ShipWind, Wind, Windage};
use super::{ADDED_MASS, Force, ShipForm, Term, Units, VARIABLES, YawInertia};
use crate::validate::Requirement;
use std::collections::BTreeMap;

/// Whether a table's coefficients hold the rigid-body terms of 4.46.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RigidBodyTerms {
    /// The table folds them in (see the module docs); `eom` converts it.
    Folded,
    /// The table is hydrodynamic only; 4.46 adds the rigid-body terms.
    Separate,
}

/// The body of a ship, in the table's units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShipBody {
    /// M (kg), or m′ = M/(½ρL³).
    pub mass: f64,
    /// The yaw inertia (kg m²), or over ½ρL⁵, about the point [`Self::yaw_inertia_about`] says.
    pub yaw_inertia: f64,
    /// About G or about midship.
    pub yaw_inertia_about: YawInertia,
    /// G ahead of midship: m, or over L.
    pub x_g: f64,
}

/// A ship's hydrodynamic table, checked, with the rigid-body terms separate.
#[derive(Debug, Clone, PartialEq)]
pub struct ShipTable {
    /// The units of every number.
    pub units: Units,
    /// The body.
    pub body: ShipBody,
    /// ρ, kg/m³ (the prime system's; optional in SI).
    pub density: Option<f64>,
    /// L, m (the prime system's; optional in SI).
    pub length: Option<f64>,
    /// U₀, m/s: the approach speed, and the prime system's reference of the surge perturbation.
    pub design_speed: f64,
    /// X_u̇, Y_v̇, Y_ṙ, N_v̇, N_ṙ, in [`ADDED_MASS`]'s order.
    pub added_mass: [f64; 5],
    /// The polynomial's coefficients, none zero, rigid-body terms separate.
    pub terms: BTreeMap<Term, f64>,
    /// How the table was given.
    pub given_as: RigidBodyTerms,
    /// What the conversion of a folded table did, one line per coefficient changed.
    pub conversions: Vec<String>,
    /// The propeller and the rudder in its slipstream, with the rate at the approach solved
    /// ([`Propulsion::at_approach`]); `None` for a ship without a propulsion model.
    pub propulsion: Option<Propulsion>,
    /// The MMG standard method's ship (its hull's terms are [`ShipTable::terms`], its added
    /// masses [`ShipTable::added_mass`] in SI; its propeller and rudder are here), for a
    /// table of that form; `None` for a polynomial table.
    pub mmg: Option<MmgShip>,
    /// The uniform current the ship moves in, where the scene gives one: its u and v are then
    /// through the water and its track over ground.
    pub current: Option<Current>,
    /// The ship's wind coefficients and areas, where the scene gives them: the air then acts
    /// on it, still or blowing ([`ShipTable::ship_wind`]).
    pub windage: Option<Windage>,
    /// The wind, where the scene gives one (it needs a windage); without one the air is still.
    pub wind: Option<Wind>,
}

/// A uniform current, constant in space and time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Current {
    /// Its speed, m/s.
    pub speed: f64,
    /// The direction it flows toward (its set), rad clockwise from north (X).
    pub toward: f64,
}

impl ShipTable {
    /// The air on the ship, for a table with a windage: the wind (still air without one) and
    /// the current the ship drifts in.
    pub fn ship_wind(&self) -> Option<ShipWind> {
        let windage = self.windage.clone()?;
        let still = Wind {
            speed: 0.0,
            from: 0.0,
            gust: None,
        };
        Some(ShipWind {
            windage,
            wind: self.wind.clone().unwrap_or(still),
            current: self.current.map_or([0.0; 2], |c| c.components()),
        })
    }
}

impl Current {
    /// Its north and east components, m/s.
    pub fn components(&self) -> [f64; 2] {
        let (sin, cos) = self.toward.sin_cos();
        [self.speed * cos, self.speed * sin]
    }
}

/// A coefficient name, read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Coefficient {
    /// An added-mass derivative, by its index in [`ADDED_MASS`].
    AddedMass(usize),
    /// A term of the polynomial.
    Term(Term),
}

/// Reads a coefficient name (see the module docs); `None` for a name that is not one.
pub fn parse_name(name: &str) -> Option<Coefficient> {
    let mut chars = name.chars();
    let force = match chars.next()? {
        'X' => Force::X,
        'Y' => Force::Y,
        'N' => Force::N,
        _ => return None,
    };
    let rest = chars.as_str();
    let rest = rest.strip_prefix('_').unwrap_or(rest);
    if let Some(rate) = rest.strip_suffix("dot") {
        let symbol = format!("{}_{rate}dot", force.letter());
        return ADDED_MASS
            .iter()
            .position(|a| *a == symbol)
            .map(Coefficient::AddedMass);
    }
    let (bias, letters) = match rest.strip_prefix('0') {
        Some(letters) => (true, letters),
        None => (false, rest),
    };
    if letters.is_empty() && !bias {
        return None;
    }
    let mut powers = [0u8; 5];
    for letter in letters.chars() {
        let index = VARIABLES.iter().position(|v| *v == letter)?;
        powers[index] = powers[index].checked_add(1)?;
    }
    Some(Coefficient::Term(Term { force, powers }))
}

/// Refuses a term that has no form in this table: a term in the effective rudder angle e
/// needs a propulsion model (e is formed on the rudder's inflow speed c), and with one a term
/// in δ or e has no power of u, v or r (the rudder's terms are on c, the hull's on U).
fn check_form(term: &Term, name: &str, propulsion: bool) -> Result<(), ShipError> {
    let [a, b, c, d, e] = term.powers;
    if e > 0 && !propulsion {
        return Err(ShipError::invalid(
            key(name),
            "a term in the effective rudder angle e needs a [propulsion] table (e is formed on \
             the rudder's inflow speed c)",
        ));
    }
    if propulsion && (d > 0 || e > 0) && a + b + c > 0 {
        return Err(ShipError::invalid(
            key(name),
            "with a propulsion model the rudder's terms are on its inflow speed c: a term in δ \
             or e cannot also be in u, v or r",
        ));
    }
    Ok(())
}

/// The coefficients of a table as the scene gives them, before the convention is applied.
#[derive(Debug, Clone, PartialEq)]
pub struct GivenTable {
    /// The units.
    pub units: Units,
    /// The body.
    pub body: ShipBody,
    /// ρ.
    pub density: Option<f64>,
    /// L.
    pub length: Option<f64>,
    /// U₀.
    pub design_speed: f64,
    /// The convention the coefficients are in.
    pub rigid_body_terms: RigidBodyTerms,
    /// Name → value, as written.
    pub coefficients: BTreeMap<String, f64>,
    /// The propulsion model, as given (the rate at the approach not yet solved).
    pub propulsion: Option<Propulsion>,
}

/// The path of a coefficient's key in a scene.
fn key(name: &str) -> String {
    format!("hydrodynamics.coefficients.{name}")
}

impl ShipTable {
    /// Checks a table and converts a folded one.
    pub fn new(given: &GivenTable) -> Result<Self, ShipError> {
        let mut added_mass = [0.0; 5];
        let mut terms: BTreeMap<Term, f64> = BTreeMap::new();
        let mut names: BTreeMap<Term, &str> = BTreeMap::new();
        for (name, &value) in &given.coefficients {
            if let Err(violation) = Requirement::Finite.check(value) {
                return Err(ShipError::invalid(key(name), violation.to_string()));
            }
            match parse_name(name) {
                None => {
                    return Err(ShipError::invalid(
                        key(name),
                        "not a coefficient name: X, Y or N, then the variables u, v, r, d \
                         (and e, the effective rudder angle) one letter per power (Yvvr), 0 \
                         for a bias term (Y0), or an added mass Xudot, Yvdot, Yrdot, Nvdot, \
                         Nrdot",
                    ));
                }
                Some(Coefficient::AddedMass(i)) => added_mass[i] = value,
                Some(Coefficient::Term(term)) => {
                    check_form(&term, name, given.propulsion.is_some())?;
                    if let Some(other) = names.insert(term, name) {
                        return Err(ShipError::invalid(
                            key(name),
                            format!("the same term as `{other}` ({term})"),
                        ));
                    }
                    terms.insert(term, value);
                }
            }
        }
        let mut table = ShipTable {
            units: given.units,
            body: given.body,
            density: given.density,
            length: given.length,
            design_speed: given.design_speed,
            added_mass,
            terms,
            given_as: given.rigid_body_terms,
            conversions: Vec::new(),
            propulsion: None,
            mmg: None,
            current: None,
            windage: None,
            wind: None,
        };
        if let Some(propulsion) = given.propulsion {
            let length = match (given.units, given.length) {
                (Units::Prime, Some(length)) => length,
                _ => {
                    return Err(ShipError::invalid(
                        "propulsion",
                        "a propulsion model is read in the prime system (units = \"prime\")",
                    ));
                }
            };
            table.propulsion = Some(propulsion.at_approach(given.design_speed, length)?);
        }
        if given.rigid_body_terms == RigidBodyTerms::Folded {
            table.unfold();
        }
        table.terms.retain(|_, value| *value != 0.0);
        table.check_mass_matrix()?;
        Ok(table)
    }

    /// The table of an MMG ship: its body in SI, its hull's terms (R′₀ as the bias −X_0,
    /// the derivatives in v′ and r′ as given, zeros left out), its added masses in SI
    /// (X_u̇ = −m′_x ½ρL²d, Y_v̇ = −m′_y ½ρL²d, N_ṙ = −J′_z ½ρL⁴d, what the mass matrix and the
    /// linear model read; the proved program reads m′_x, m′_y, J′_z themselves), and the
    /// propeller rate that balances the approach at `design_speed`, held in every run unless
    /// `held` gives another.
    pub fn mmg(
        body: ShipBody,
        parameters: MmgParameters,
        (design_speed, held): (f64, Option<f64>),
    ) -> Result<Self, ShipError> {
        let ship = &parameters.particulars;
        let (hull, added) = (&parameters.hull, &parameters.added_mass);
        let mass_scale = 0.5 * ship.density * ship.length * ship.length * ship.draft;
        let inertia_scale = mass_scale * ship.length * ship.length;
        let t = |force, powers: [u8; 2]| Term {
            force,
            powers: [0, powers[0], powers[1], 0, 0],
        };
        let lateral = |force, [v, r, vvv, vvr, vrr, rrr]: [f64; 6]| {
            [
                (t(force, [1, 0]), v),
                (t(force, [0, 1]), r),
                (t(force, [3, 0]), vvv),
                (t(force, [2, 1]), vvr),
                (t(force, [1, 2]), vrr),
                (t(force, [0, 3]), rrr),
            ]
        };
        let mut terms: BTreeMap<Term, f64> = [
            (t(Force::X, [0, 0]), -hull.resistance),
            (t(Force::X, [2, 0]), hull.x_vv),
            (t(Force::X, [1, 1]), hull.x_vr),
            (t(Force::X, [0, 2]), hull.x_rr),
            (t(Force::X, [4, 0]), hull.x_vvvv),
        ]
        .into_iter()
        .collect();
        let y = [
            hull.y_v, hull.y_r, hull.y_vvv, hull.y_vvr, hull.y_vrr, hull.y_rrr,
        ];
        let n = [
            hull.n_v, hull.n_r, hull.n_vvv, hull.n_vvr, hull.n_vrr, hull.n_rrr,
        ];
        terms.extend(lateral(Force::Y, y));
        terms.extend(lateral(Force::N, n));
        terms.retain(|_, value| *value != 0.0);
        let table = ShipTable {
            units: Units::Dimensional,
            body: ShipBody {
                x_g: ship.centre_of_gravity,
                ..body
            },
            density: Some(ship.density),
            length: Some(ship.length),
            design_speed,
            added_mass: [
                -added.surge * mass_scale,
                -added.sway * mass_scale,
                0.0,
                0.0,
                -added.yaw * inertia_scale,
            ],
            terms,
            given_as: RigidBodyTerms::Separate,
            conversions: Vec::new(),
            propulsion: None,
            mmg: Some(MmgShip::new(parameters, design_speed, held)?),
            current: None,
            windage: None,
            wind: None,
        };
        table.check_mass_matrix()?;
        Ok(table)
    }

    /// The rigid-body parts a folded table holds, per term: m′ (or M) and m′x_G′ (or M x_G)
    /// with the sign each has on the right of 4.46.
    fn folded_parts(&self) -> [(Term, f64, &'static str); 6] {
        let m = self.body.mass;
        let mx = self.body.mass * self.body.x_g;
        let (mass, moment) = match self.units {
            Units::Prime => ("m′", "m′x_G′"),
            Units::Dimensional => ("M", "M x_G"),
        };
        let t = |force, [a, b, c, d]: [u8; 4]| Term {
            force,
            powers: [a, b, c, d, 0],
        };
        let rigid_r = match self.units {
            // −m′(1 + u′)r′: a part in r′ and a part in u′r′.
            Units::Prime => -m,
            Units::Dimensional => 0.0,
        };
        let rigid_r_moment = match self.units {
            Units::Prime => -mx,
            Units::Dimensional => 0.0,
        };
        [
            (t(Force::X, [0, 1, 1, 0]), m, mass),
            (t(Force::X, [0, 0, 2, 0]), mx, moment),
            (t(Force::Y, [0, 0, 1, 0]), rigid_r, mass),
            (t(Force::Y, [1, 0, 1, 0]), -m, mass),
            (t(Force::N, [0, 0, 1, 0]), rigid_r_moment, moment),
            (t(Force::N, [1, 0, 1, 0]), -mx, moment),
        ]
    }

    /// Takes the rigid-body parts out of a folded table (hydrodynamic = folded − rigid).
    fn unfold(&mut self) {
        for (term, rigid, what) in self.folded_parts() {
            if rigid == 0.0 {
                continue;
            }
            let folded = self.terms.get(&term).copied().unwrap_or(0.0);
            let separate = folded - rigid;
            self.terms.insert(term, separate);
            let sign = if rigid < 0.0 { '+' } else { '−' };
            self.conversions.push(format!(
                "{term}: {folded:e} (folded) {sign} {what} {:e} = {separate:e}",
                rigid.abs()
            ));
        }
    }

    /// The table's form: the MMG standard method's where it has an MMG ship.
    pub fn form(&self) -> ShipForm {
        match self.mmg {
            Some(_) => ShipForm::Mmg,
            None => ShipForm::Polynomial,
        }
    }

    /// The SI mass matrix of 4.46 with the added mass, rows (surge, sway, yaw).
    pub fn mass_matrix(&self) -> [[f64; 3]; 3] {
        let scale = |n: i32| self.si_scale(n);
        let mass = self.body.mass * scale(3);
        let x_g = self.body.x_g * scale(1);
        let inertia_o = match self.body.yaw_inertia_about {
            YawInertia::AboutG => self.body.yaw_inertia * scale(5) + mass * x_g * x_g,
            YawInertia::AboutMidship => self.body.yaw_inertia * scale(5),
        };
        let [x_ud, y_vd, y_rd, n_vd, n_rd] = self.added_mass;
        [
            [mass - x_ud * scale(3), 0.0, 0.0],
            [0.0, mass - y_vd * scale(3), mass * x_g - y_rd * scale(4)],
            [
                0.0,
                mass * x_g - n_vd * scale(4),
                inertia_o - n_rd * scale(5),
            ],
        ]
    }

    /// ½ρLⁿ in the prime system (Lⁿ for n = 1, a length), 1 in SI.
    pub fn si_scale(&self, n: i32) -> f64 {
        match self.units {
            Units::Dimensional => 1.0,
            Units::Prime => {
                let length = self.length.unwrap_or(f64::NAN);
                if n == 1 {
                    length
                } else {
                    0.5 * self.density.unwrap_or(f64::NAN) * length.powi(n)
                }
            }
        }
    }

    /// Refuses a mass matrix that is not positive definite: a body whose added mass makes it
    /// accelerate against a force has no physical meaning and no solution.
    fn check_mass_matrix(&self) -> Result<(), ShipError> {
        let m = self.mass_matrix();
        let key = "hydrodynamics.coefficients";
        if m[0][0] <= 0.0 {
            return Err(ShipError::invalid(
                key,
                format!("the surge mass M − X_u̇ = {:e} is not positive", m[0][0]),
            ));
        }
        let symmetric_part = |i: usize, j: usize| 0.5 * (m[i][j] + m[j][i]);
        let det = m[1][1] * m[2][2] - symmetric_part(1, 2).powi(2);
        if m[1][1] <= 0.0 || m[2][2] <= 0.0 || det <= 0.0 {
            return Err(ShipError::invalid(
                key,
                format!(
                    "the sway–yaw mass matrix [[{:e}, {:e}], [{:e}, {:e}]] is not positive \
                     definite: check the signs of Y_v̇, Y_ṙ, N_v̇, N_ṙ and the yaw inertia",
                    m[1][1], m[1][2], m[2][1], m[2][2]
                ),
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn term(force: Force, [a, b, c, d]: [u8; 4]) -> Coefficient {
        Coefficient::Term(Term {
            force,
            powers: [a, b, c, d, 0],
        })
    }

    #[test]
    fn names_are_read_as_published_tables_write_them() {
        assert_eq!(parse_name("Yvvr"), Some(term(Force::Y, [0, 2, 1, 0])));
        assert_eq!(parse_name("Xrv"), Some(term(Force::X, [0, 1, 1, 0])));
        assert_eq!(parse_name("Y_vvr"), Some(term(Force::Y, [0, 2, 1, 0])));
        assert_eq!(parse_name("N0"), Some(term(Force::N, [0, 0, 0, 0])));
        assert_eq!(parse_name("Y0uu"), Some(term(Force::Y, [2, 0, 0, 0])));
        assert_eq!(parse_name("Xudd"), Some(term(Force::X, [1, 0, 0, 2])));
        assert_eq!(parse_name("Nrdot"), Some(Coefficient::AddedMass(4)));
        assert_eq!(parse_name("Xudot"), Some(Coefficient::AddedMass(0)));
        for bad in ["Xvdot", "Y", "Zv", "Yvq", "", "Y_", "yv"] {
            assert_eq!(parse_name(bad), None, "{bad}");
        }
    }
}
