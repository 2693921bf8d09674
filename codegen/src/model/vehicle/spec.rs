//! What a vehicle's spec makes of its table: the terms, the added mass, the loads, the
//! residuals of the six equations about O, the energies, the parameters and the inputs.

use super::names::VELOCITY_LETTERS;
use super::{
    AddedMassCoriolis, AddedMassEntries, AddedMassEntry, DENSITY, Factor, ForceTerm, InertiaAbout,
    LENGTH, Load, Propeller, Units, VehicleError, VehicleSpec, inverse_entry, parse_added_mass,
    parse_term, symbolic,
};
use crate::derivation::energy::rigid_body_kinetic_energy;
use crate::derivation::kinematics::body_to_space;
use crate::derivation::quaternion::{Quaternion, rotation_matrix};
use crate::derivation::tensor_about_origin;
use crate::derivation::vehicle::{
    LOADS, VELOCITIES, centre_of_gravity, fluid_kinetic_energy, kirchhoff, rigid_body_about_origin,
    symmetric_matrix,
};
use crate::model::Kinematics;
use crate::model::system::Parameter;
use crate::symbolic::{Expr, Mat3, Rational, SymbolicError, Vec3};
use std::borrow::Cow;

/// The position of O in space axes (Z down) and the attitude, after ν.
fn kinematic_state(kinematics: Kinematics) -> Vec<&'static str> {
    let attitude: &[&str] = match kinematics {
        Kinematics::Euler => &["phi", "theta", "psi"],
        Kinematics::Quaternion => &["q0", "q1", "q2", "q3"],
    };
    let mut state = vec!["x", "y", "z"];
    state.extend(attitude);
    state
}

fn parameter(symbol: impl Into<Cow<'static, str>>, doc: impl Into<Cow<'static, str>>) -> Parameter {
    Parameter {
        symbol: symbol.into(),
        doc: doc.into(),
    }
}

impl VehicleSpec {
    /// The table's force terms, read under the spec's convention; a name listed twice, two
    /// names of one term, or a name that does not read is refused.
    pub fn force_terms(&self) -> Result<Vec<ForceTerm>, VehicleError> {
        self.check_controls()?;
        let mut terms: Vec<ForceTerm> = Vec::new();
        for name in &self.terms {
            if terms.iter().any(|t| &t.name == name) {
                return Err(VehicleError::ListedTwice(name.clone()));
            }
            let term = parse_term(name, self.convention, &self.controls)?;
            let key = self.dimensional_key(&term)?;
            let same = terms
                .iter()
                .find(|t| t.load == term.load && self.dimensional_key(t).ok() == Some(key.clone()));
            if let Some(same) = same {
                let product: Vec<String> = key.iter().map(Factor::to_string).collect();
                let meaning = match self.units {
                    Units::Dimensional => term.meaning(),
                    Units::Prime => format!("{} once U = u is written out", product.join("·")),
                };
                return Err(VehicleError::SameTerm(
                    same.name.clone(),
                    term.name.clone(),
                    meaning,
                ));
            }
            terms.push(term);
        }
        Ok(terms)
    }

    /// The factors of a term's product in SI, sorted: its own, and in the prime system the
    /// u's of u^(2 − j) ([`Self::term_scale`]), so that `Yv` and `Yuv` have one key there.
    pub fn dimensional_key(&self, term: &ForceTerm) -> Result<Vec<Factor>, VehicleError> {
        let mut key = term.product_key();
        if self.units == Units::Prime {
            let (linear, angular) = term.velocity_powers();
            let missing =
                usize::try_from(2 - (linear + angular)).map_err(|_| VehicleError::Prime {
                    name: term.name.clone(),
                    why: format!(
                        "{} velocity factors: with U = u a term has at most two, or it would \
                         divide by u",
                        linear + angular
                    ),
                })?;
            key.extend(std::iter::repeat_n(
                Factor {
                    variable: "u".into(),
                    absolute: false,
                },
                missing,
            ));
            key.sort();
        }
        Ok(key)
    }

    /// ½ρLⁿ in the prime system, 1 in SI.
    fn prime_scale(&self, length_power: i32) -> Result<Expr, VehicleError> {
        match self.units {
            Units::Dimensional => Ok(Expr::int(1)),
            Units::Prime => {
                let half = Expr::constant(Rational::new(1.into(), 2.into()));
                let length = Expr::symbol(LENGTH)
                    .pow(length_power)
                    .map_err(symbolic("vehicle"))?;
                Ok(&(&half * &Expr::symbol(DENSITY)) * &length)
            }
        }
    }

    /// What turns a term's coefficient times its product into SI: 1 in SI; in the prime
    /// system ½ρL^(2 + a + m)·u^(2 − j) for j velocity factors, a of them angular, m = 1 for
    /// a moment (see the module docs). A term of more than two velocity factors is refused.
    pub fn term_scale(&self, term: &ForceTerm) -> Result<Expr, VehicleError> {
        if self.units == Units::Dimensional {
            return Ok(Expr::int(1));
        }
        let missing = self.dimensional_key(term)?.len() - term.product_key().len();
        let (_, angular) = term.velocity_powers();
        let moment = i32::from(term.load.is_moment());
        let surge = (0..missing).fold(Expr::int(1), |a, _| a * Expr::symbol("u"));
        Ok(&self.prime_scale(2 + angular + moment)? * &surge)
    }

    /// What turns an added-mass entry into SI: 1, or ½ρL^(3 + m + a) in the prime system, m = 1
    /// for a moment's row and a = 1 for an angular velocity's column.
    fn added_mass_scale(&self, row: usize, column: usize) -> Result<Expr, VehicleError> {
        let power = 3 + i32::from(row >= 3) + i32::from(column >= 3);
        self.prime_scale(power)
    }

    fn check_controls(&self) -> Result<(), VehicleError> {
        for name in &self.controls {
            let refuse = |why: &str| VehicleError::Control {
                name: name.clone(),
                why: why.into(),
            };
            let identifier = name.chars().next().is_some_and(|c| c.is_ascii_lowercase())
                && name.chars().all(|c| c.is_ascii_alphanumeric());
            if !identifier {
                return Err(refuse("a control is lower-case letters and digits"));
            }
            if name.starts_with(VELOCITY_LETTERS) {
                return Err(refuse(
                    "it starts with a velocity's letter, so a term's name could be read two ways",
                ));
            }
            if name.contains("dot") {
                return Err(refuse("`dot` marks an added-mass entry"));
            }
        }
        Ok(())
    }

    /// The added-mass entries, one per symmetric pair: the first name given for a pair is its
    /// parameter; a later name of the same pair is its partner (returned second).
    pub fn added_mass_entries(&self) -> Result<AddedMassEntries, VehicleError> {
        let mut entries: Vec<AddedMassEntry> = Vec::new();
        let mut partners = Vec::new();
        for name in &self.added_mass {
            let entry = parse_added_mass(name)?;
            let pair = |e: &AddedMassEntry| (e.row.min(e.column), e.row.max(e.column));
            match entries.iter().find(|e| pair(e) == pair(&entry)) {
                Some(first) if first.name == entry.name => {
                    return Err(VehicleError::ListedTwice(name.clone()));
                }
                Some(first) => partners.push((first.name.clone(), entry.name.clone())),
                None => entries.push(entry),
            }
        }
        Ok((entries, partners))
    }

    /// M_A = −(the table's entries), symmetric.
    pub fn added_mass_matrix(&self) -> Result<[[Expr; 6]; 6], VehicleError> {
        let (entries, _) = self.added_mass_entries()?;
        let table = symmetric_matrix(|i, j| {
            entries
                .iter()
                .find(|e| (e.row.min(e.column), e.row.max(e.column)) == (i, j))
                .map(|e| e.name.clone())
                .unwrap_or_default()
        });
        let mut matrix: [[Expr; 6]; 6] =
            std::array::from_fn(|_| std::array::from_fn(|_| Expr::zero()));
        for (i, row) in matrix.iter_mut().enumerate() {
            for (j, entry) in row.iter_mut().enumerate() {
                *entry = -&(&self.added_mass_scale(i, j)? * &table[i][j]);
            }
        }
        Ok(matrix)
    }

    /// The symbols of the given inertia tensor, row-major upper triangle order
    /// (xx, yy, zz, xy, yz, xz), pruned products left out.
    fn inertia_symbols(&self) -> Vec<(&'static str, &'static str)> {
        let all = match self.inertia {
            InertiaAbout::Origin => [
                ("Ixx", "Ixx"),
                ("Iyy", "Iyy"),
                ("Izz", "Izz"),
                ("Ixy", "Ixy"),
                ("Iyz", "Iyz"),
                ("Ixz", "Ixz"),
            ],
            InertiaAbout::Gravity => [
                ("Ixx", "Ixx_G"),
                ("Iyy", "Iyy_G"),
                ("Izz", "Izz_G"),
                ("Ixy", "Ixy_G"),
                ("Iyz", "Iyz_G"),
                ("Ixz", "Ixz_G"),
            ],
        };
        all.into_iter()
            .filter(|(entry, _)| !self.symmetry.pruned().contains(entry))
            .collect()
    }

    /// The tensor about O in the spec's parameters, as substitutions for `Ixx` … `Ixz`.
    fn inertia_about_origin(&self) -> Result<Vec<(&'static str, Expr)>, SymbolicError> {
        let given: Vec<(&str, &str)> = self.inertia_symbols();
        let value = |entry: &str| -> Expr {
            given
                .iter()
                .find(|(e, _)| *e == entry)
                .map(|(_, symbol)| Expr::symbol(symbol))
                .unwrap_or_default()
        };
        let entries = ["Ixx", "Iyy", "Izz", "Ixy", "Iyz", "Ixz"];
        match self.inertia {
            InertiaAbout::Origin => Ok(entries.iter().map(|e| (*e, value(e))).collect()),
            InertiaAbout::Gravity => {
                let about_g = [
                    ("Ixx_G", value("Ixx")),
                    ("Iyy_G", value("Iyy")),
                    ("Izz_G", value("Izz")),
                    ("Ixy_G", value("Ixy")),
                    ("Iyz_G", value("Iyz")),
                    ("Izx_G", value("Ixz")),
                ];
                let tensor = tensor_about_origin()?;
                let at = [(0, 0), (1, 1), (2, 2), (0, 1), (1, 2), (0, 2)];
                entries
                    .iter()
                    .zip(at)
                    .map(|(e, (r, c))| Ok((*e, tensor.0[r][c].subs_all(&about_g)?)))
                    .collect()
            }
        }
    }

    /// k_b = Rᵀ(0, 0, 1): the downward vertical in body axes.
    fn vertical_in_body(&self) -> Vec3 {
        let rotation: Mat3 = match self.kinematics {
            Kinematics::Euler => body_to_space(),
            Kinematics::Quaternion => rotation_matrix(&Quaternion::symbols()),
        };
        rotation
            .transpose()
            .mul_vec(&Vec3::new(Expr::zero(), Expr::zero(), Expr::int(1)))
    }

    fn centre_of_buoyancy() -> Vec3 {
        Vec3::symbols(["x_B", "y_B", "z_B"])
    }

    /// The restoring loads of the weight at G and the buoyancy at B, in body axes.
    pub fn restoring(&self) -> [Expr; 6] {
        if !self.hydrostatics {
            return std::array::from_fn(|_| Expr::zero());
        }
        let k = self.vertical_in_body();
        let (weight, buoyancy) = (Expr::symbol("weight"), Expr::symbol("buoyancy"));
        let force = k.scale(&(&weight - &buoyancy));
        let moment = centre_of_gravity()
            .cross(&k.scale(&weight))
            .sub(&Self::centre_of_buoyancy().cross(&k.scale(&buoyancy)));
        let [x, y, z] = force.0;
        let [kk, m, n] = moment.0;
        [x, y, z, kk, m, n]
    }

    /// V = (B − W)z − (W r_G − B r_B)·k_b: the potential of the weight and the buoyancy, Z down.
    pub(super) fn potential_energy(&self) -> Expr {
        let k = self.vertical_in_body();
        let (weight, buoyancy) = (Expr::symbol("weight"), Expr::symbol("buoyancy"));
        let lever = centre_of_gravity()
            .scale(&weight)
            .sub(&Self::centre_of_buoyancy().scale(&buoyancy));
        &(&buoyancy - &weight) * &Expr::symbol("z") - lever.dot(&k)
    }

    /// The value of a term's product: |x| read from the input `abs_x`.
    fn product(term: &ForceTerm) -> Expr {
        term.factors
            .iter()
            .map(|f| {
                if f.absolute {
                    Expr::symbol(&format!("abs_{}", f.variable))
                } else {
                    Expr::symbol(&f.variable)
                }
            })
            .fold(Expr::int(1), |a, b| a * b)
    }

    /// The right sides: the table's terms, the propeller, the restoring loads and the applied
    /// loads, per load.
    pub fn loads(&self) -> Result<[Expr; 6], VehicleError> {
        let terms = self.force_terms()?;
        let restoring = self.restoring();
        let mut loads: [Expr; 6] = std::array::from_fn(|i| restoring[i].clone());
        for term in &terms {
            let value =
                Expr::symbol(&term.symbol()) * Self::product(term) * self.term_scale(term)?;
            loads[term.load.index()] = &loads[term.load.index()] + &value;
        }
        if self.propeller != Propeller::None {
            loads[0] = &loads[0] + &Expr::symbol("X_prop");
            loads[3] = &loads[3] + &Expr::symbol("K_prop");
        }
        if self.applied_loads {
            for (load, symbol) in loads.iter_mut().zip(LOADS) {
                *load = &*load + &Expr::symbol(symbol);
            }
        }
        Ok(loads)
    }

    /// The residuals of the six equations about O, left − right, in the spec's parameters:
    /// the rigid body (derived, `derivation::vehicle`), the added mass on the left with
    /// Kirchhoff's terms where derived, and the loads.
    pub fn residuals(&self) -> Result<[Expr; 6], VehicleError> {
        let err = symbolic("vehicle");
        let rigid = rigid_body_about_origin().map_err(&err)?;
        let loads = self.loads()?;
        let load_symbols: Vec<(&str, Expr)> = LOADS.iter().copied().zip(loads).collect();
        let inertia = self.inertia_about_origin().map_err(&err)?;
        let added_mass = self.added_mass_matrix()?;
        let fluid = match self.added_mass_coriolis {
            AddedMassCoriolis::Derived => kirchhoff(&added_mass).map_err(&err)?,
            AddedMassCoriolis::Folded => std::array::from_fn(|i| {
                VELOCITIES
                    .iter()
                    .enumerate()
                    .map(|(j, v)| &added_mass[i][j] * &Expr::symbol(&format!("{v}_dot")))
                    .sum()
            }),
        };
        let mut residuals: [Expr; 6] = std::array::from_fn(|_| Expr::zero());
        for i in 0..6 {
            // The loads first: an applied load F_x is its own symbol again afterwards.
            let body = rigid[i].subs_all(&load_symbols).map_err(&err)?;
            residuals[i] = &body.subs_all(&inertia).map_err(&err)? + &fluid[i];
        }
        Ok(residuals)
    }

    /// T = ½M|v + ω × r_G|² + ½ωᵀ\[I_G\]ω (4.32, v_G by 4.5) + ½νᵀM_Aν: the body's and the
    /// fluid's kinetic energy, in the spec's parameters.
    pub fn kinetic_energy(&self) -> Result<Expr, VehicleError> {
        let err = symbolic("vehicle");
        let omega = Vec3::symbols(["p", "q", "r"]);
        let v_g = Vec3::symbols(["u", "v", "w"]).add(&omega.cross(&centre_of_gravity()));
        let [u, v, w] = v_g.0;
        // 4.32 in the tensor about G; that tensor is the one about O less Steiner's part.
        let about_o = self.inertia_about_origin().map_err(&err)?;
        let correction = tensor_about_origin().map_err(&err)?;
        let at = [(0, 0), (1, 1), (2, 2), (0, 1), (1, 2), (0, 2)];
        let about_g_symbols = ["Ixx_G", "Iyy_G", "Izz_G", "Ixy_G", "Iyz_G", "Izx_G"];
        let mut tensor_g: Vec<(&str, Expr)> = Vec::new();
        for (((entry, value), (r, c)), symbol) in about_o.iter().zip(at).zip(about_g_symbols) {
            let steiner = &correction.0[r][c] - &Expr::symbol(symbol);
            tensor_g.push((entry, value - &steiner));
        }
        let mut substitutions = vec![("u", u), ("v", v), ("w", w)];
        substitutions.extend(tensor_g);
        let body = rigid_body_kinetic_energy()
            .and_then(|t| t.subs_all(&substitutions))
            .map_err(&err)?;
        let fluid = fluid_kinetic_energy(&self.added_mass_matrix()?).map_err(&err)?;
        Ok(body + fluid)
    }

    /// The parameters, in order: the body, G, the hydrostatics, the added mass, the
    /// propeller's constants, the table's coefficients, then the entries of (M_RB + M_A)⁻¹.
    pub fn parameters(&self) -> Result<Vec<Parameter>, VehicleError> {
        let mut parameters = vec![parameter("M", "mass M")];
        let about = match self.inertia {
            InertiaAbout::Origin => "about O, the table's origin",
            InertiaAbout::Gravity => "about G",
        };
        for (entry, symbol) in self.inertia_symbols() {
            let doc = if entry[1..2] == entry[2..3] {
                format!("moment of inertia {entry} {about} (4.13)")
            } else {
                let (a, b) = (&entry[1..2], &entry[2..3]);
                format!("product of inertia {entry} = −∫{a}{b} dm {about} (4.14)")
            };
            parameters.push(parameter(symbol, doc));
        }
        for axis in ["x", "y", "z"] {
            parameters.push(parameter(
                format!("{axis}_G"),
                format!("position {axis}_G of G from O along body {axis}"),
            ));
        }
        if self.hydrostatics {
            parameters.push(parameter("weight", "weight W, N"));
            parameters.push(parameter("buoyancy", "buoyancy B, N"));
            for axis in ["x", "y", "z"] {
                parameters.push(parameter(
                    format!("{axis}_B"),
                    format!("position {axis}_B of the centre of buoyancy from O along body {axis}"),
                ));
            }
        }
        if self.units == Units::Prime {
            parameters.push(parameter(
                DENSITY,
                "water density ρ, kg/m³, of the prime system",
            ));
            parameters.push(parameter(
                LENGTH,
                "length L, m, the prime system's unit of length",
            ));
        }
        let prime = match self.units {
            Units::Dimensional => "",
            Units::Prime => " (prime)",
        };
        let (entries, partners) = self.added_mass_entries()?;
        for entry in &entries {
            let partner = partners
                .iter()
                .find(|(first, _)| *first == entry.name)
                .map(|(_, second)| format!(" (and its symmetric partner {second})"))
                .unwrap_or_default();
            parameters.push(parameter(
                entry.name.clone(),
                format!(
                    "added mass {}{partner}{prime}: {} per {}-acceleration",
                    entry.name,
                    Load::ALL[entry.row].letter(),
                    VELOCITIES[entry.column]
                ),
            ));
        }
        if self.propeller == Propeller::Constant {
            parameters.push(parameter("X_prop", "propeller's thrust X_prop, N"));
            parameters.push(parameter(
                "K_prop",
                "propeller's torque K_prop on the body, N m",
            ));
        }
        for term in self.force_terms()? {
            parameters.push(parameter(
                term.symbol(),
                format!(
                    "hydrodynamic coefficient {}{prime} of {} in {}",
                    term.name,
                    term.meaning(),
                    term.load.letter()
                ),
            ));
        }
        for (i, row) in VELOCITIES.iter().enumerate() {
            for (j, column) in VELOCITIES.iter().enumerate().skip(i) {
                parameters.push(parameter(
                    inverse_entry(i, j),
                    format!(
                        "entry ({row}, {column}) of (M_RB + M_A)⁻¹, from `inverse_mass_matrix`"
                    ),
                ));
            }
        }
        Ok(parameters)
    }

    /// The velocities and controls whose absolute value the table's terms read, in order:
    /// the input `abs_x` is |x|.
    pub fn absolute_values(&self) -> Result<Vec<String>, VehicleError> {
        let terms = self.force_terms()?;
        let mut order: Vec<String> = VELOCITIES.iter().map(|v| v.to_string()).collect();
        order.extend(self.controls.iter().cloned());
        Ok(order
            .into_iter()
            .filter(|x| {
                terms
                    .iter()
                    .any(|t| t.factors.iter().any(|f| f.absolute && &f.variable == x))
            })
            .collect())
    }

    /// The inputs, in order: the controls, the propeller's (where inputs), the applied loads
    /// (where asked for), then `abs_x` for each |x| the terms read.
    pub fn inputs(&self) -> Result<Vec<String>, VehicleError> {
        let mut inputs = self.controls.clone();
        if self.propeller == Propeller::Input {
            inputs.extend(["X_prop".into(), "K_prop".into()]);
        }
        if self.applied_loads {
            inputs.extend(LOADS.iter().map(|l| l.to_string()));
        }
        inputs.extend(
            self.absolute_values()?
                .into_iter()
                .map(|x| format!("abs_{x}")),
        );
        Ok(inputs)
    }

    /// The state: ν, the position of O in space axes (Z down), the attitude.
    pub fn state(&self) -> Vec<&'static str> {
        let mut state = VELOCITIES.to_vec();
        state.extend(kinematic_state(self.kinematics));
        state
    }
}
