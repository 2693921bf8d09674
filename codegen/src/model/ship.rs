//! Ship manoeuvring: 4.46 at midship with the hydrodynamic forces a scene lists.
//!
//! The chapter writes the planar equations at midship (4.46) for exactly this use, "with the
//! fluid forces measured in model tests about midship". The forces are a polynomial in
//! (u, v, r, δ) with one coefficient per term the scene gives, and nothing else: a table of
//! eight terms emits eight products, a table of forty emits forty ("model only what a scene
//! requires"). The added mass enters on the left, so the mass matrix is
//!
//! ```text
//! [[M − X_u̇,  0,           0                    ],
//!  [0,        M − Y_v̇,     M x_G − Y_ṙ          ],
//!  [0,        M x_G − N_v̇, I_zz + M x_G² − N_ṙ  ]]
//! ```
//!
//! with I_zz about G (4.46), or `I_O − M x_G²` substituted where the scene gives the yaw inertia
//! about midship. It depends on parameters only, so it is inverted once per parameter set
//! (adjugate over determinant, as every other model). The rigid-body terms of 4.46 (M v r,
//! M x_G r², M u r, M x_G u r) are written by the derivation; a table that folds them into
//! its coefficients is converted before it reaches this module.
//!
//! Two unit systems are accepted, each read exactly as the table gives it:
//! - dimensional: a term `Y_vvr` contributes `Y_vvr v² r` newtons;
//! - the prime system (forces over ½ρU²L², moments over ½ρU²L³, mass over ½ρL³, I_zz over
//!   ½ρL⁵, lengths over L, u and v over U, r over U/L, the surge variable the perturbation
//!   (u − U₀)/U, with U = √(u² + v²) the instantaneous speed): a term contributes
//!   `½ρL²U² · Y'_vvr (v/U)² (rL/U)`. The scaling is part of the derivation, so the proof
//!   covers it; the one quantity that is not a polynomial, U, is an input the caller computes.
//!
//! **Propulsion** (a spec with [`ShipSpec::propulsion`], after Abkowitz's model of the Esso
//! Osaka, Trans. SNAME 88, 1980): the propeller rate n is an input, and the caller computes
//! beside U what is not a polynomial in it: |n|, the propeller's induced axial velocity u_A far
//! behind the disk and the rudder's inflow speed c (both from u and n by momentum theory). Then
//! - the thrust law and the resistance add to X: ½ρL²(T′_uu u² + T′_un L n u + T′_nn L² n|n|)
//!   − ½ρL² R′_uu u² (in SI, T_uu u² + T_un n u + T_nn n|n| − R_uu u²);
//! - the rudder works on c: the effective rudder angle is e = δ − (v + x_R r)/c, the flow's
//!   angle at the rudder (x_R its position ahead of midship, negative aft) taken off δ; a term
//!   in e (`X_ee`, `Y_eee`) contributes ½ρL²c² X′_ee e² (× L for a moment), and a term in δ
//!   alone ½ρL²c² Y′_d δ, with the change of the rudder's share of the linear derivatives
//!   with c, −½ρL²Y′_d (c − c₀)(v + x_R r), c₀ the inflow speed at the approach, where the
//!   table's Y′_v and Y′_r were identified;
//! - a bias term is the propeller's: ½ρL²(u_A/2)² Y′_0 (× L for a moment).
//!
//! e is formed here from δ, v, r and c, so the proof covers it too.
//!
//! **The MMG standard method's form** (a spec with [`ShipForm::Mmg`]; H. Yasukawa and
//! Y. Yoshimura, *J. Mar. Sci. Technol.* 20:37–52, 2015): the body in SI (M, the yaw inertia,
//! x_G), the added masses non-dimensional, m′_x and m′_y on ½ρL²d and J′_z on ½ρL⁴d (d the
//! draft), and the equations of motion the method writes at midship,
//!
//! ```text
//! (M + m_x) u̇ − (M + m_y) v r − M x_G r² = X
//! (M + m_y) v̇ + (M + m_x) u r + M x_G ṙ = Y
//! (I_zz + M x_G² + J_z) ṙ + M x_G (v̇ + u r) = N
//! ```
//!
//! which are 4.46 with the loads X_H + X_a − m_x u̇ + m_y v r, Y_H + Y_a − m_y v̇ − m_x u r and
//! N_H + N_a − J_z ṙ (the added mass's Munk moment (m_x − m_y)uv is in the hull's N′_v, as the
//! method fits it). The hull's terms are in v′ = v/U and r′ = rL/U (no term in u or δ): a
//! term contributes ½ρLdU² · Y′_vvr v′²r′, ×L for a moment, and a bias term in X is −R′₀'s
//! ½ρLdU² R′₀. The propeller's and the rudder's loads (X_a, Y_a, N_a) are not polynomials
//! (a wake law in exp(−C₁|β_P|), the race's square roots, an angle of attack through
//! atan2): the caller computes them beside U and the program reads them as inputs, added to
//! the right side, which is proved with them.
//!
//! **Applied loads** (a spec with [`ShipSpec::applied`]): loads computed beside the program,
//! the wind's on the hull and superstructure above water, which are neither polynomials nor
//! constant (they follow the relative wind's angle through a table, and the heading), enter a
//! polynomial ship as they enter an MMG ship: X, Y, N inputs added to the right side, proved
//! with it.
//!
//! **A uniform current** (a spec with [`ShipSpec::current`]): the hydrodynamic forces see the
//! ship's velocity through the water, so 4.46's u and v are taken through the water, and the
//! track is carried by the current, Ẋ = u cos ψ − v sin ψ + V_N, Ẏ = u sin ψ + v cos ψ + V_E
//! (4.44 plus the current's north and east components, inputs). For a current constant in
//! space and time nothing else changes: over ground u = u_r + u_c, v = v_r + v_c with the
//! current's body-axis components turning at −r (u̇_c = r v_c, v̇_c = −r u_c), so 4.46's
//! u̇ − vr and v̇ + ur are u̇_r − v_r r and v̇_r + u_r r: the rigid body's terms keep their
//! form in the velocity through the water (Fossen's property of a constant irrotational
//! current, *Handbook of Marine Craft Hydrodynamics and Motion Control*, 2011).

use super::families::inverse_names;
use super::solve::solve_linear;
use super::system::{BuildError, Group, Parameter, System};
use crate::derivation::energy::rigid_body_kinetic_energy;
use crate::derivation::kinematics::rotation_z;
use crate::derivation::planar;
use crate::symbolic::{Expr, Rational, SymbolicError, Vec3};
use std::borrow::Cow;
use std::fmt;

/// Which of the three planar loads a term belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Force {
    /// The surge force X.
    X,
    /// The sway force Y.
    Y,
    /// The yaw moment N.
    N,
}

impl Force {
    /// The three, in the order of 4.46's equations.
    pub const ALL: [Force; 3] = [Force::X, Force::Y, Force::N];

    /// `X`, `Y` or `N`.
    pub fn letter(self) -> char {
        match self {
            Force::X => 'X',
            Force::Y => 'Y',
            Force::N => 'N',
        }
    }
}

/// The variables of the force polynomial, in the order of their powers in [`Term::powers`]:
/// u, v, r, δ, and the effective rudder angle e of a spec with propulsion (module docs).
pub const VARIABLES: [char; 5] = ['u', 'v', 'r', 'd', 'e'];

/// One term of the hydrodynamic polynomial: `coefficient · u^a v^b r^c δ^d e^k`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Term {
    /// The load it adds to.
    pub force: Force,
    /// The powers of u, v, r, δ and e; all zero for a constant (bias) term.
    pub powers: [u8; 5],
}

impl Term {
    /// The coefficient's symbol: the load then the variables, one letter per power, in the
    /// order u, v, r, d, e (`Y_vvr`, `X_uu`, `N_d`, `Y_eee`), or `_0` for a constant (`Y_0`).
    pub fn symbol(&self) -> String {
        let letters: String = VARIABLES
            .iter()
            .zip(self.powers)
            .flat_map(|(letter, power)| std::iter::repeat_n(*letter, power as usize))
            .collect();
        let letters = if letters.is_empty() {
            "0".into()
        } else {
            letters
        };
        format!("{}_{letters}", self.force.letter())
    }

    /// The monomial it multiplies, with the variables named as given: `v²r`, `1` for a bias.
    pub fn monomial(&self, names: [&str; 5]) -> String {
        let superscript = |power: u8| match power {
            1 => String::new(),
            2 => "²".into(),
            3 => "³".into(),
            n => format!("^{n}"),
        };
        let factors: String = names
            .iter()
            .zip(self.powers)
            .filter(|(_, power)| *power > 0)
            .map(|(name, power)| format!("{name}{}", superscript(power)))
            .collect();
        if factors.is_empty() {
            "1".into()
        } else {
            factors
        }
    }

    /// The total power of u, v and r: the speed-like variables the prime system scales by U.
    fn kinematic_degree(&self) -> i32 {
        i32::from(self.powers[0]) + i32::from(self.powers[1]) + i32::from(self.powers[2])
    }
}

impl fmt::Display for Term {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.symbol())
    }
}

/// The added-mass derivatives on the left of 4.46, by their symbols.
pub const ADDED_MASS: [&str; 5] = ["X_udot", "Y_vdot", "Y_rdot", "N_vdot", "N_rdot"];

/// The units a table's numbers are in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Units {
    /// SI: newtons, newton metres, kilograms, metres, seconds, radians.
    Dimensional,
    /// The prime system (see the module docs).
    Prime,
}

/// About which point the scene gives the yaw moment of inertia.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum YawInertia {
    /// I_zz about G, as 4.46 writes it.
    AboutG,
    /// I_O about midship, the origin: I_zz = I_O − M x_G² (4.45's parallel axes).
    AboutMidship,
}

/// How the hydrodynamic forces are structured (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ShipForm {
    /// One polynomial table of the whole ship's forces (Abkowitz's; the Mariner's), its added
    /// mass as the derivatives X_u̇ … N_ṙ, in SI or the prime system.
    Polynomial,
    /// The MMG standard method's: the body in SI, the added masses m′_x, m′_y, J′_z, the
    /// hull's polynomial in v′ and r′ on ½ρLdU², the propeller's and the rudder's loads applied.
    Mmg,
}

/// What a ship model is made of.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ShipSpec {
    /// The units of every parameter.
    pub units: Units,
    /// Which yaw inertia the parameters give.
    pub yaw_inertia: YawInertia,
    /// The polynomial's terms, each once.
    pub terms: Vec<Term>,
    /// Whether the ship has a propeller, with its thrust law, and a rudder on its inflow speed
    /// c (module docs); a spec without one reads no n, c or u_A.
    pub propulsion: bool,
    /// The polynomial table's form or the MMG standard method's (module docs); an MMG spec is
    /// in [`Units::Dimensional`] (its body's units) and has no [`ShipSpec::propulsion`] (its
    /// propeller and rudder are applied loads).
    pub form: ShipForm,
    /// Whether the ship moves in a uniform current: the velocities of 4.46 are then through
    /// the water, and the track (4.44) adds the current's north and east components, inputs
    /// [`CURRENT_INPUTS`] (module docs).
    pub current: bool,
    /// Whether loads computed beside the program act on the ship (the wind's): a polynomial
    /// spec then reads [`APPLIED_LOADS`] as an MMG spec does, added to the right side (module
    /// docs); an MMG spec reads them anyway.
    pub applied: bool,
}

/// The parameters of propulsion, by their symbols, after the body's, the added mass and the
/// prime scales: the rudder's position x_R (over L in the prime system), the rudder's inflow
/// speed c₀ at the approach, the thrust law's T_uu, T_un, T_nn and the resistance R_uu.
pub const PROPULSION: [&str; 6] = ["x_R", "c0", "T_uu", "T_un", "T_nn", "R_uu"];

/// The inputs of propulsion the caller computes, after δ̇ and U: the propeller rate n (rev/s),
/// |n|, the induced axial velocity u_A far behind the disk and the rudder's inflow speed c
/// (m/s).
pub const PROPULSION_INPUTS: [&str; 4] = ["n", "n_abs", "u_A", "c"];

/// The MMG form's added masses by their symbols (m′_x, m′_y on ½ρL²d; J′_z on ½ρL⁴d), after
/// the body's.
pub const MMG_ADDED_MASS: [&str; 3] = ["m_x", "m_y", "J_z"];

/// The MMG form's scales, by their symbols, after its added masses: ρ, L and the draft d.
pub const MMG_SCALES: [&str; 3] = [DENSITY, LENGTH, DRAFT];
const DRAFT: &str = "draft";

/// The applied loads, inputs after δ̇ and U (and propulsion's): X, Y, N about midship (N, N,
/// N m), which the caller computes: an MMG ship's propeller and rudder, the wind's loads.
pub const APPLIED_LOADS: [&str; 3] = ["X_applied", "Y_applied", "N_applied"];

/// A uniform current's north and east components (m/s), inputs after every other of a spec
/// with [`ShipSpec::current`].
pub const CURRENT_INPUTS: [&str; 2] = ["current_north", "current_east"];

/// The prime system's scales, by their symbols: ρ, L, and U₀ (the reference of the surge
/// perturbation), parameters of a prime-system model after the body's and the added mass.
pub const PRIME_SCALES: [&str; 3] = [DENSITY, LENGTH, DESIGN_SPEED];
const DENSITY: &str = "rho";
const LENGTH: &str = "L";
const DESIGN_SPEED: &str = "U0";

/// The state of every ship model: 4.46's velocities, 4.44's track and heading, the rudder.
pub const STATE: [&str; 7] = ["u", "v", "r", "X", "Y", "psi", "delta"];

impl ShipSpec {
    /// The parameters, in order: the body's, the added mass, the prime system's scales (in
    /// the prime system), then one coefficient per term.
    pub fn parameters(&self) -> Vec<Parameter> {
        let prime = self.units == Units::Prime;
        let unit = |dimensional: &'static str, primed: &'static str| match self.units {
            Units::Dimensional => dimensional,
            Units::Prime => primed,
        };
        let mut parameters = vec![
            parameter(self.mass(), unit("mass M", "mass m′ = M/(½ρL³)")),
            parameter(
                self.inertia(),
                match (self.yaw_inertia, prime) {
                    (YawInertia::AboutG, false) => "yaw inertia I_zz about G",
                    (YawInertia::AboutMidship, false) => "yaw inertia I_O about midship",
                    (YawInertia::AboutG, true) => "yaw inertia I_zz′ about G, over ½ρL⁵",
                    (YawInertia::AboutMidship, true) => "yaw inertia I_O′ about midship, over ½ρL⁵",
                },
            ),
            parameter(
                self.centre(),
                unit(
                    "x_G, the position of G ahead of midship (4.45)",
                    "x_G′ = x_G/L, G ahead of midship",
                ),
            ),
        ];
        if self.form == ShipForm::Mmg {
            self.mmg_parameters(&mut parameters);
            return parameters;
        }
        let added_mass = [
            "added mass X_u̇: surge force per surge acceleration",
            "added mass Y_v̇: sway force per sway acceleration",
            "added mass Y_ṙ: sway force per yaw acceleration",
            "added mass N_v̇: yaw moment per sway acceleration",
            "added mass N_ṙ: yaw moment per yaw acceleration",
        ];
        for (symbol, doc) in ADDED_MASS.iter().zip(added_mass) {
            parameters.push(Parameter {
                symbol: Cow::Borrowed(symbol),
                doc: Cow::Owned(format!("{doc}{}", unit("", " (prime)"))),
            });
        }
        if prime {
            let docs = [
                "water density ρ",
                "length L, the prime system's unit of length",
                "the design speed U₀ of the surge perturbation",
            ];
            for (symbol, doc) in PRIME_SCALES.iter().zip(docs) {
                parameters.push(parameter(symbol, doc));
            }
        }
        if self.propulsion {
            let docs = [
                unit(
                    "x_R, the rudder's position ahead of midship, m",
                    "x_R′ = x_R/L, the rudder's position ahead of midship",
                ),
                "c₀, the rudder's inflow speed at the approach, m/s",
                unit(
                    "thrust law: the coefficient of u²",
                    "thrust law: T′_uu, the coefficient of u² over ½ρL²",
                ),
                unit(
                    "thrust law: the coefficient of n u",
                    "thrust law: T′_un, the coefficient of n u over ½ρL³",
                ),
                unit(
                    "thrust law: the coefficient of n|n|",
                    "thrust law: T′_nn, the coefficient of n|n| over ½ρL⁴",
                ),
                unit(
                    "resistance: the coefficient of −u²",
                    "resistance: R′_uu, the coefficient of −u² over ½ρL²",
                ),
            ];
            for (symbol, doc) in PROPULSION.iter().zip(docs) {
                parameters.push(parameter(symbol, doc));
            }
        }
        for term in &self.terms {
            let variables = match self.units {
                Units::Dimensional => ["u", "v", "r", "δ", "e"],
                Units::Prime => ["u′", "v′", "r′", "δ", "e"],
            };
            parameters.push(Parameter {
                symbol: Cow::Owned(term.symbol()),
                doc: Cow::Owned(format!(
                    "hydrodynamic derivative: the coefficient of {} in {}{}",
                    term.monomial(variables),
                    term.force.letter(),
                    unit("", " (prime)")
                )),
            });
        }
        parameters
    }

    /// The MMG form's parameters after the body's: the added masses, the scales, the hull's
    /// terms.
    fn mmg_parameters(&self, parameters: &mut Vec<Parameter>) {
        let docs = [
            "added mass m′_x in surge, over ½ρL²d",
            "added mass m′_y in sway, over ½ρL²d",
            "added moment of inertia J′_z in yaw, over ½ρL⁴d",
            "water density ρ",
            "length L between perpendiculars",
            "draft d",
        ];
        let symbols = MMG_ADDED_MASS.iter().chain(&MMG_SCALES);
        for (symbol, doc) in symbols.zip(docs) {
            parameters.push(parameter(symbol, doc));
        }
        for term in &self.terms {
            let scale = match term.force {
                Force::N => "½ρL²dU²",
                Force::X | Force::Y => "½ρLdU²",
            };
            let doc = match term.powers {
                [0, 0, 0, 0, 0] => {
                    format!("the hull's bias in {} over {scale}", term.force.letter())
                }
                _ => format!(
                    "the hull's derivative: the coefficient of {} in {} over {scale}",
                    term.monomial(["u", "v′", "r′", "δ", "e"]),
                    term.force.letter()
                ),
            };
            parameters.push(Parameter {
                symbol: Cow::Owned(term.symbol()),
                doc: Cow::Owned(doc),
            });
        }
    }

    /// The inputs: the rudder rate, in the prime system and the MMG form the speed U, with
    /// propulsion [`PROPULSION_INPUTS`], in the MMG form or with [`ShipSpec::applied`]
    /// [`APPLIED_LOADS`].
    pub fn inputs(&self) -> Vec<&'static str> {
        let mut inputs = match (self.form, self.units) {
            (ShipForm::Mmg, _) => vec!["delta_rate", "U"],
            (ShipForm::Polynomial, Units::Dimensional) => vec!["delta_rate"],
            (ShipForm::Polynomial, Units::Prime) => vec!["delta_rate", "U"],
        };
        if self.propulsion {
            inputs.extend(PROPULSION_INPUTS);
        }
        if self.reads_applied_loads() {
            inputs.extend(APPLIED_LOADS);
        }
        if self.current {
            inputs.extend(CURRENT_INPUTS);
        }
        inputs
    }

    /// Whether the right side adds [`APPLIED_LOADS`]: in the MMG form, or with
    /// [`ShipSpec::applied`].
    pub fn reads_applied_loads(&self) -> bool {
        self.form == ShipForm::Mmg || self.applied
    }

    /// The symbols of the body's three parameters, in this spec's units: the mass, the yaw
    /// inertia (about the point the spec says), the position of G.
    pub fn body_symbols(&self) -> [&'static str; 3] {
        [self.mass(), self.inertia(), self.centre()]
    }

    fn mass(&self) -> &'static str {
        match self.units {
            Units::Dimensional => "M",
            Units::Prime => "mass_prime",
        }
    }

    fn inertia(&self) -> &'static str {
        match (self.units, self.yaw_inertia) {
            (Units::Dimensional, YawInertia::AboutG) => "Izz",
            (Units::Dimensional, YawInertia::AboutMidship) => "Izz_midship",
            (Units::Prime, YawInertia::AboutG) => "izz_prime",
            (Units::Prime, YawInertia::AboutMidship) => "izz_midship_prime",
        }
    }

    fn centre(&self) -> &'static str {
        match self.units {
            Units::Dimensional => "x_G",
            Units::Prime => "x_g_prime",
        }
    }

    /// ½ρLⁿ in the prime system, 1 in SI: what turns a prime quantity of length dimension n
    /// (mass 3, yaw inertia 5, a force coefficient 2 + the power of r) into SI.
    fn scale(&self, length_power: i32) -> Result<Expr, SymbolicError> {
        match self.units {
            Units::Dimensional => Ok(Expr::int(1)),
            Units::Prime => {
                let half = Expr::constant(Rational::new(1.into(), 2.into()));
                Ok(&(&half * &Expr::symbol(DENSITY)) * &Expr::symbol(LENGTH).pow(length_power)?)
            }
        }
    }

    /// The SI values of the body's parameters, as expressions in this spec's parameters:
    /// M, I_zz about G, x_G.
    fn rigid_body(&self) -> Result<[(&'static str, Expr); 3], SymbolicError> {
        let mass = &self.scale(3)? * &Expr::symbol(self.mass());
        let x_g = match self.units {
            Units::Dimensional => Expr::symbol("x_G"),
            Units::Prime => &Expr::symbol(LENGTH) * &Expr::symbol(self.centre()),
        };
        let given = &self.scale(5)? * &Expr::symbol(self.inertia());
        let izz = match self.yaw_inertia {
            YawInertia::AboutG => given,
            YawInertia::AboutMidship => &given - &(&mass * &x_g.pow(2)?),
        };
        Ok([("M", mass), ("Izz", izz), ("x_G", x_g)])
    }

    /// One load of the polynomial, in SI, as an expression in the state, the inputs and the
    /// parameters; with propulsion, the thrust law and the resistance in X.
    pub fn force(&self, force: Force) -> Result<Expr, SymbolicError> {
        let mut sum = Expr::zero();
        for term in self.terms.iter().filter(|t| t.force == force) {
            let coefficient = Expr::symbol(&term.symbol());
            sum = &sum + &(&coefficient * &self.monomial_value(term)?);
        }
        if self.propulsion && force == Force::X {
            sum = &sum + &self.thrust()?;
        }
        if self.reads_applied_loads() {
            let index = Force::ALL.iter().position(|f| *f == force).unwrap_or(0);
            sum = &sum + &Expr::symbol(APPLIED_LOADS[index]);
        }
        Ok(sum)
    }

    /// ½ρLd in the MMG form: the hull's force per U² of a coefficient (× L for a moment).
    fn mmg_scale(&self) -> Expr {
        let half = Expr::constant(Rational::new(1.into(), 2.into()));
        &(&half * &Expr::symbol(DENSITY)) * &(&Expr::symbol(LENGTH) * &Expr::symbol(DRAFT))
    }

    /// What one term's coefficient multiplies, in SI (see the module docs).
    fn monomial_value(&self, term: &Term) -> Result<Expr, SymbolicError> {
        let moment_length = i32::from(term.force == Force::N);
        let [a, b, c, d, k] = term.powers.map(i32::from);
        if self.form == ShipForm::Mmg {
            // ½ρLdU² v′^b r′^c = ½ρLd L^c U^(2−b−c) v^b r^c, × L for a moment.
            let length = Expr::symbol(LENGTH).pow(c + moment_length)?;
            let speed = Expr::symbol("U").pow(2 - b - c)?;
            let variables = &Expr::symbol("v").pow(b)? * &Expr::symbol("r").pow(c)?;
            return Ok(&(&self.mmg_scale() * &length) * &(&speed * &variables));
        }
        if self.propulsion && a + b + c == 0 {
            // On the rudder's inflow speed c (a term in e or in δ alone) or the propeller's
            // induced velocity (a bias): ½ρL²c² e^k δ^d, ½ρL²(u_A/2)², × L for a moment.
            let scale = self.scale(2 + moment_length)?;
            if k == 0 && d == 0 {
                let half = Expr::constant(Rational::new(1.into(), 2.into()));
                return Ok(&scale * &(&half * &Expr::symbol("u_A")).pow(2)?);
            }
            let inflow = Expr::symbol("c");
            let angle = self.effective_rudder_angle()?;
            let mut value =
                &(&scale * &inflow.pow(2)?) * &(&angle.pow(k)? * &Expr::symbol("delta").pow(d)?);
            if k == 0 && d == 1 {
                // The rudder's share of Y_v and Y_r changes with c from c₀, where they were
                // identified: −Y_d (c − c₀)(v + x_R r).
                let change = &inflow - &Expr::symbol("c0");
                value = &value - &(&scale * &(&change * &self.rudder_lateral_velocity()?));
            }
            return Ok(value);
        }
        Ok(match self.units {
            Units::Dimensional => {
                let [u, v, r, delta] = ["u", "v", "r", "delta"].map(Expr::symbol);
                &(&u.pow(a)? * &v.pow(b)?) * &(&r.pow(c)? * &delta.pow(d)?)
            }
            Units::Prime => {
                // ½ρL²U² · (Δu/U)^a (v/U)^b (rL/U)^c δ^d, times L for a moment.
                let surge = Expr::symbol("u") - Expr::symbol(DESIGN_SPEED);
                let speed = Expr::symbol("U").pow(2 - term.kinematic_degree())?;
                let variables = &(&surge.pow(a)? * &Expr::symbol("v").pow(b)?)
                    * &(&Expr::symbol("r").pow(c)? * &Expr::symbol("delta").pow(d)?);
                &(&self.scale(2 + c + moment_length)? * &speed) * &variables
            }
        })
    }

    /// v + x_R r: the lateral velocity of the water's flow at the rudder, relative to the hull.
    fn rudder_lateral_velocity(&self) -> Result<Expr, SymbolicError> {
        let position = &self.length()? * &Expr::symbol("x_R");
        Ok(&Expr::symbol("v") + &(&position * &Expr::symbol("r")))
    }

    /// e = δ − (v + x_R r)/c: the rudder's angle to its inflow.
    fn effective_rudder_angle(&self) -> Result<Expr, SymbolicError> {
        let drift = &self.rudder_lateral_velocity()? * &Expr::symbol("c").pow(-1)?;
        Ok(&Expr::symbol("delta") - &drift)
    }

    /// L in the prime system (what turns x_R′ and n L into SI), 1 in SI.
    fn length(&self) -> Result<Expr, SymbolicError> {
        Ok(match self.units {
            Units::Dimensional => Expr::int(1),
            Units::Prime => Expr::symbol(LENGTH),
        })
    }

    /// The thrust law less the resistance: ½ρL²(T′_uu u² + T′_un L n u + T′_nn L² n|n|
    /// − R′_uu u²), or its SI form.
    fn thrust(&self) -> Result<Expr, SymbolicError> {
        let [u, n, n_abs] = ["u", "n", "n_abs"].map(Expr::symbol);
        let length = self.length()?;
        let uu = &(&Expr::symbol("T_uu") - &Expr::symbol("R_uu")) * &u.pow(2)?;
        let un = &(&Expr::symbol("T_un") * &length) * &(&n * &u);
        let nn = &(&Expr::symbol("T_nn") * &length.pow(2)?) * &(&n * &n_abs);
        Ok(&self.scale(2)? * &(&(&uu + &un) + &nn))
    }

    /// The added-mass loads, X_u̇ u̇, Y_v̇ v̇ + Y_ṙ ṙ and N_v̇ v̇ + N_ṙ ṙ, in SI; in the MMG
    /// form −m_x u̇ + m_y v r, −m_y v̇ − m_x u r and −J_z ṙ (module docs).
    fn added_mass(&self, force: Force) -> Result<Expr, SymbolicError> {
        if self.form == ShipForm::Mmg {
            let mass = |symbol: &str| &self.mmg_scale() * &Expr::symbol(symbol);
            let inertia = &mass("J_z") * &Expr::symbol(LENGTH).pow(2)?;
            let [u, v, r] = ["u", "v", "r"].map(Expr::symbol);
            return Ok(match force {
                Force::X => {
                    let length = Expr::symbol(LENGTH);
                    let (m_x, m_y) = (&mass("m_x") * &length, &mass("m_y") * &length);
                    &(&m_y * &(&v * &r)) - &(&m_x * &Expr::symbol("u_dot"))
                }
                Force::Y => {
                    let length = Expr::symbol(LENGTH);
                    let (m_x, m_y) = (&mass("m_x") * &length, &mass("m_y") * &length);
                    -&(&(&m_y * &Expr::symbol("v_dot")) + &(&m_x * &(&u * &r)))
                }
                Force::N => -&(&(&inertia * &Expr::symbol(LENGTH)) * &Expr::symbol("r_dot")),
            });
        }
        let term = |symbol: &str, rate: &str, length_power: i32| -> Result<Expr, SymbolicError> {
            Ok(&(&self.scale(length_power)? * &Expr::symbol(symbol)) * &Expr::symbol(rate))
        };
        match force {
            Force::X => term("X_udot", "u_dot", 3),
            Force::Y => Ok(&term("Y_vdot", "v_dot", 3)? + &term("Y_rdot", "r_dot", 4)?),
            Force::N => Ok(&term("N_vdot", "v_dot", 4)? + &term("N_rdot", "r_dot", 5)?),
        }
    }

    /// The residuals of 4.46 (left − right) with the loads the hydrodynamic polynomial plus
    /// the added mass, in this spec's parameters.
    pub fn residuals(&self) -> Result<[Expr; 3], SymbolicError> {
        let at_g = planar::residuals_at_g()?;
        let at_midship = planar::residuals_at_midship(&at_g)?;
        let mut loads = Vec::new();
        for (force, symbol) in Force::ALL.iter().zip(["F_x", "F_y", "M_z"]) {
            loads.push((symbol, &self.force(*force)? + &self.added_mass(*force)?));
        }
        let rigid = self.rigid_body()?;
        let mut residuals = Vec::new();
        for residual in at_midship {
            residuals.push(residual.subs_all(&loads)?.subs_all(&rigid)?);
        }
        Ok(residuals.try_into().expect("4.46 has three equations"))
    }

    /// Whether a term has a form here: a term in e needs propulsion, and with propulsion a
    /// term in δ or e has no power of u, v or r (the rudder's terms are on c, the hull's on U).
    pub fn reads(&self, term: &Term) -> bool {
        let [a, b, c, d, k] = term.powers;
        if self.form == ShipForm::Mmg {
            // The hull's terms: in v′ and r′ alone (the rudder is an applied load).
            return a == 0 && d == 0 && k == 0;
        }
        let rudder = d > 0 || k > 0;
        if !self.propulsion {
            return k == 0;
        }
        !rudder || a + b + c == 0
    }

    /// T = ½M(u² + (v + x_G r)²) + ½I_zz r²: the rigid body's kinetic energy (4.32), the
    /// fluid's left out.
    fn kinetic_energy(&self) -> Result<Expr, SymbolicError> {
        let [u, v, r] = ["u", "v", "r"].map(Expr::symbol);
        let in_plane = [
            ("w", Expr::zero()),
            ("p", Expr::zero()),
            ("q", Expr::zero()),
            ("u", u),
            ("v", &v + &(&Expr::symbol("x_G") * &r)),
            ("r", r),
        ];
        rigid_body_kinetic_energy()?
            .subs_all(&in_plane)?
            .subs_all(&self.rigid_body()?)
    }
}

fn parameter(symbol: &'static str, doc: &'static str) -> Parameter {
    Parameter {
        symbol: Cow::Borrowed(symbol),
        doc: Cow::Borrowed(doc),
    }
}

/// The ship model of a spec: 4.46 with its forces, solved for (u̇, v̇, ṙ) with the constant
/// mass matrix inverted once (surge alone, sway and yaw as a 2×2 block), the track 4.44, the
/// heading, and the rudder angle driven by the input `delta_rate`.
pub fn ship(name: &str, spec: &ShipSpec) -> Result<System, BuildError> {
    let symbolic = |source| BuildError::Symbolic {
        model: name.into(),
        source,
    };
    let mut seen = std::collections::BTreeSet::new();
    if let Some(twice) = spec.terms.iter().find(|t| !seen.insert(**t)) {
        return Err(BuildError::Verification {
            model: name.into(),
            what: format!("the term {twice} is listed twice"),
            residual: twice.symbol(),
        });
    }
    if spec.form == ShipForm::Mmg && (spec.units != Units::Dimensional || spec.propulsion) {
        return Err(BuildError::Verification {
            model: name.into(),
            what: "an MMG spec has its body in SI (Units::Dimensional) and its propeller and \
                   rudder as applied loads (no propulsion model)"
                .into(),
            residual: "form".into(),
        });
    }
    if let Some(term) = spec.terms.iter().find(|t| !spec.reads(t)) {
        return Err(BuildError::Verification {
            model: name.into(),
            what: format!(
                "the term {term} {}",
                if spec.form == ShipForm::Mmg {
                    "is not one of the MMG hull's, in v′ and r′ alone"
                } else if spec.propulsion {
                    "mixes the rudder (on its inflow speed c) with u, v or r (on U)"
                } else {
                    "is in the effective rudder angle e, which needs a propulsion model"
                }
            ),
            residual: term.symbol(),
        });
    }
    // The mass matrix is block diagonal: surge alone, then sway and yaw together.
    let [surge, sway, yaw] = spec.residuals().map_err(symbolic)?;
    let surge = solve_linear(name, &[surge], &["u_dot"], "inv_surge_mass")?;
    let sway_yaw = solve_linear(name, &[sway, yaw], &["v_dot", "r_dot"], "inv_det")?;
    let mut outputs = surge.accelerations(&surge.rest);
    outputs.extend(sway_yaw.accelerations(&sway_yaw.rest));
    let velocity = Vec3::new(Expr::symbol("u"), Expr::symbol("v"), Expr::zero());
    let [mut x_rate, mut y_rate, _] = rotation_z("psi").mul_vec(&velocity).0;
    if spec.current {
        // Through the water at (u, v), carried over ground by the current.
        let [north, east] = CURRENT_INPUTS.map(Expr::symbol);
        x_rate = &x_rate + &north;
        y_rate = &y_rate + &east;
    }
    outputs.extend([
        x_rate,
        y_rate,
        Expr::symbol("r"),
        Expr::symbol("delta_rate"),
    ]);
    let names = |solution, axes| inverse_names(solution, "inv_mass_matrix", "M_A", axes);
    let mut coefficient_names = names(&surge, &["u"]);
    coefficient_names.extend(names(&sway_yaw, &["v", "r"]));
    let mut reciprocals = surge.reciprocals.clone();
    reciprocals.extend(sway_yaw.reciprocals.iter().cloned());
    Ok(System {
        name: name.into(),
        title: "Ship manoeuvring at midship: 4.46 with hydrodynamic forces".into(),
        equations: vec!["4.45", "4.46", "4.44"],
        parameters: spec.parameters(),
        reciprocals,
        state: STATE.to_vec(),
        inputs: spec.inputs(),
        stages: vec![],
        outputs,
        groups: vec![
            Group {
                first: 0,
                comment: "4.46 with the added mass and the hydrodynamic polynomial: surge, \
                          sway and yaw at midship"
                    .into(),
            },
            Group {
                first: 3,
                comment: "4.44: the track of midship in space-fixed axes, and the heading".into(),
            },
            Group {
                first: 6,
                comment: "the rudder angle, at the rate its servo gives".into(),
            },
        ],
        kinetic_energy: Some(spec.kinetic_energy().map_err(symbolic)?),
        energy_formula: Some("T = ½M(u² + (v + x_G r)²) + ½I_zz r², the rigid body's"),
        potential_energy: None,
        potential_formula: None,
        coefficient_names,
    })
}
