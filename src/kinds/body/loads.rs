//! What acts on a scene's body, as the inputs of its model.
//!
//! A model takes its inputs in its own axes (body axes about G for the spatial and body-fixed
//! planar models, space axes for the space-fixed planar model, a moment about the pivot for
//! the pendulum and the top). A scene states loads where they are natural — gravity and
//! buoyancy in space, thrust in body axes, damping on the body velocities — and
//! [`SceneLoads`] turns them into the model's inputs at each state, through the attitude the
//! state carries.
//!
//! A force acts at G unless the scene names its point (`force_body_at`, `force_space_at`, body
//! axes from G): a force F at r_P adds the moment r_P × F about G (4.2), evaluated in body axes
//! at each state, since a space force turns in the body as the body turns.
//!
//! Where every load has a potential (gravity, buoyancy, constant space forces wherever they
//! act, the planar and the pendulum's constant moment), [`SceneLoads::potential_energy`] gives it, so a run can
//! report the total energy and its drift; body-axis forces, damping and loads given as time
//! tables have none. The pendulum's and the top's own weight is in their models.
//!
//! A force or moment given as a time table ([`super::table`]) is held in the family's
//! [`TimedLoad`]s, its constant field zero; [`SceneLoads::inputs_at`] reads the tables at a
//! time, and [`SceneLoads::prepared_on`] on one piece of a run between breakpoints.

use super::file::{LoadsTable, Timed};
use super::table::{Target, TimeTable, TimedLoad};
use super::{Body, Selection};
use crate::models::{Family, Kinematics, Loads, attitude};
use crate::scene::Problem;
use crate::validate::Requirement;
use nalgebra::Vector3;

/// A scene's loads, by family.
#[derive(Debug, Clone, PartialEq)]
pub enum SceneLoads {
    /// The pendulum.
    Pendulum(PendulumLoads),
    /// The heavy top.
    Top(TopLoads),
    /// A planar body.
    Planar(PlanarLoads),
    /// A spatial body.
    Spatial(SpatialLoads),
}

/// The pendulum's: a constant moment about the pivot and damping of θ̇.
#[derive(Debug, Clone, PartialEq)]
pub struct PendulumLoads {
    /// Constant moment, N m.
    pub moment: f64,
    /// Linear damping coefficient.
    pub linear: f64,
    /// Quadratic damping coefficient.
    pub quadratic: f64,
    /// The loads given as time tables (`moment`).
    pub tables: Vec<TimedLoad>,
}

/// The top's: a constant moment about the pivot in body axes and damping of (p, q, r).
#[derive(Debug, Clone, PartialEq)]
pub struct TopLoads {
    /// Constant moment, body axes.
    pub moment_body: [f64; 3],
    /// Linear damping of (p, q, r).
    pub linear: [f64; 3],
    /// Quadratic damping of (p, q, r).
    pub quadratic: [f64; 3],
    /// The loads given as time tables (`moment_body`).
    pub tables: Vec<TimedLoad>,
}

/// A planar body's.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanarLoads {
    /// Whether the model's state is space-fixed (4.39) rather than body-fixed.
    pub space_fixed: bool,
    /// Constant force, body axes.
    pub force_body: [f64; 2],
    /// Constant force, space axes.
    pub force_space: [f64; 2],
    /// Where `force_body` acts, body axes from G (zero: at G).
    pub force_body_at: [f64; 2],
    /// Where `force_space` acts, body axes from G (zero: at G).
    pub force_space_at: [f64; 2],
    /// Constant moment about the vertical.
    pub moment: f64,
    /// Linear damping of (u, v, r).
    pub linear: [f64; 3],
    /// Quadratic damping of (u, v, r).
    pub quadratic: [f64; 3],
    /// The loads given as time tables (`force_body`, `force_space`, `moment`).
    pub tables: Vec<TimedLoad>,
}

/// A spatial body's.
#[derive(Debug, Clone, PartialEq)]
pub struct SpatialLoads {
    /// Euler angles or a quaternion in the state.
    pub kinematics: Kinematics,
    /// The weight M g, N, along +Z.
    pub weight: f64,
    /// The buoyancy B, N, along −Z.
    pub buoyancy: f64,
    /// The centre of buoyancy relative to G, body axes.
    pub buoyancy_centre: [f64; 3],
    /// Constant force, body axes.
    pub force_body: [f64; 3],
    /// Constant force, space axes.
    pub force_space: [f64; 3],
    /// Where `force_body` acts, body axes from G (zero: at G).
    pub force_body_at: [f64; 3],
    /// Where `force_space` acts, body axes from G (zero: at G).
    pub force_space_at: [f64; 3],
    /// Constant moment, body axes.
    pub moment_body: [f64; 3],
    /// Constant moment, space axes.
    pub moment_space: [f64; 3],
    /// Linear damping of (u, v, w, p, q, r).
    pub linear: [f64; 6],
    /// Quadratic damping of (u, v, w, p, q, r).
    pub quadratic: [f64; 6],
    /// The loads given as time tables (`force_body`, `force_space`, `moment_body`,
    /// `moment_space`).
    pub tables: Vec<TimedLoad>,
}

mod values;

use values::*;

impl SceneLoads {
    /// The loads of a scene's `[loads]` table for the selected model and body.
    pub(crate) fn from_table(
        table: &LoadsTable,
        selection: &Selection,
        body: &Body,
    ) -> Result<Self, LoadError> {
        let mut tables = Vec::new();
        Ok(match (selection.info.family, body) {
            (Family::Pendulum, _) => SceneLoads::Pendulum(PendulumLoads {
                moment: timed_scalar("moment", &table.moment, (Target::Moment, &mut tables))?,
                linear: damping::<1>("linear_damping", &table.linear_damping)?[0],
                quadratic: damping::<1>("quadratic_damping", &table.quadratic_damping)?[0],
                tables,
            }),
            (Family::Top, _) => SceneLoads::Top(TopLoads {
                moment_body: timed(
                    "moment_body",
                    &table.moment_body,
                    (Target::MomentBody, &mut tables),
                )?,
                linear: damping("linear_damping", &table.linear_damping)?,
                quadratic: damping("quadratic_damping", &table.quadratic_damping)?,
                tables,
            }),
            (Family::Spatial, Body::Spatial { mass, .. }) => {
                SceneLoads::Spatial(SpatialLoads::from_table(table, selection, *mass)?)
            }
            (family, _) => {
                let forces = Forces::<2>::read(table, &mut tables)?;
                SceneLoads::Planar(PlanarLoads {
                    space_fixed: family == Family::PlanarSpaceFixed,
                    force_body: forces.body,
                    force_space: forces.space,
                    force_body_at: forces.body_at,
                    force_space_at: forces.space_at,
                    moment: timed_scalar("moment", &table.moment, (Target::Moment, &mut tables))?,
                    linear: damping("linear_damping", &table.linear_damping)?,
                    quadratic: damping("quadratic_damping", &table.quadratic_damping)?,
                    tables,
                })
            }
        })
    }

    /// True when nothing acts on the body but its model's own field.
    pub fn is_free(&self) -> bool {
        match self {
            SceneLoads::Pendulum(l) => {
                all_zero([&l.moment, &l.linear, &l.quadratic]) && l.tables.is_empty()
            }
            SceneLoads::Top(l) => {
                all_zero(l.moment_body.iter().chain(&l.linear).chain(&l.quadratic))
                    && l.tables.is_empty()
            }
            SceneLoads::Planar(l) => {
                l.is_conservative() && all_zero(l.force_space.iter().chain([&l.moment]))
            }
            SceneLoads::Spatial(l) => l.is_conservative() && !l.is_fixed_in_space(),
        }
    }

    /// The weight M g, N, of a spatial body on which uniform gravity at G is the only load
    /// (`None` for any other scene): such a field exerts no moment about G, so the rotation
    /// is torque-free and G falls freely, which is what `lie-midpoint` integrates.
    pub fn uniform_gravity_only(&self) -> Option<f64> {
        match self {
            SceneLoads::Spatial(l) if l.is_weight_alone() => Some(l.weight),
            _ => None,
        }
    }

    /// Whether a spatial body with a quaternion attitude turns free of any moment about G:
    /// nothing acts on it, or uniform gravity at G alone ([`uniform_gravity_only`](
    /// Self::uniform_gravity_only)). The geometric integrator applies to exactly these.
    pub fn rotation_is_torque_free(&self) -> bool {
        matches!(
            self,
            SceneLoads::Spatial(SpatialLoads {
                kinematics: Kinematics::Quaternion,
                ..
            })
        ) && (self.is_free() || self.uniform_gravity_only().is_some())
    }

    /// Whether a load with a potential of its own is present, so that a trajectory has
    /// potential and total energy columns even where the model has no field of its own.
    pub fn has_potential(&self) -> bool {
        match self {
            SceneLoads::Pendulum(l) => l.moment != 0.0 && l.is_conservative(),
            SceneLoads::Top(_) => false,
            SceneLoads::Planar(l) => {
                l.is_conservative() && !all_zero(l.force_space.iter().chain([&l.moment]))
            }
            SceneLoads::Spatial(l) => l.is_conservative() && l.is_fixed_in_space(),
        }
    }

    /// The inputs of the model at a state, into `out` (the model's input layout): every
    /// load evaluated, zero ones included, a time table at t = 0. A run evaluates
    /// [`prepared`](Self::prepared) loads, which skip what is zero.
    pub fn inputs(&self, state: &[f64], out: &mut [f64]) {
        self.inputs_at(0.0, state, out);
    }

    /// [`inputs`](Self::inputs) at time `t`: a time table read at `t` (a step's new value
    /// from its own time on, the end values held outside the table).
    pub fn inputs_at(&self, t: f64, state: &[f64], out: &mut [f64]) {
        let every = Acting {
            any: true,
            damping: true,
            in_space: self.is_fixed_in_space(),
        };
        if self.tables().is_empty() {
            self.inputs_acting(every, state, out);
        } else {
            let now = self.with_tables_read(|table| table.at(t));
            now.inputs_acting(every, state, out);
        }
    }

    /// The times at which a load given as a table jumps or turns, ascending, each once: where
    /// a run is cut into pieces (see [`super::table`]).
    pub fn breakpoints(&self) -> Vec<f64> {
        let mut times: Vec<f64> = self
            .tables()
            .iter()
            .flat_map(|timed| timed.table.times().iter().copied())
            .collect();
        times.sort_by(f64::total_cmp);
        times.dedup();
        times
    }

    /// The loads given as time tables.
    fn tables(&self) -> &[TimedLoad] {
        match self {
            SceneLoads::Pendulum(l) => &l.tables,
            SceneLoads::Top(l) => &l.tables,
            SceneLoads::Planar(l) => &l.tables,
            SceneLoads::Spatial(l) => &l.tables,
        }
    }

    /// These loads with every table read by `value` into its load: constants only, and no
    /// allocation (their table list is empty).
    fn with_tables_read(&self, value: impl Fn(&TimeTable) -> [f64; 3]) -> SceneLoads {
        let mut now = match self {
            SceneLoads::Pendulum(l) => SceneLoads::Pendulum(PendulumLoads {
                tables: Vec::new(),
                ..*l
            }),
            SceneLoads::Top(l) => SceneLoads::Top(TopLoads {
                tables: Vec::new(),
                ..*l
            }),
            SceneLoads::Planar(l) => SceneLoads::Planar(PlanarLoads {
                tables: Vec::new(),
                ..*l
            }),
            SceneLoads::Spatial(l) => SceneLoads::Spatial(SpatialLoads {
                tables: Vec::new(),
                ..*l
            }),
        };
        for timed in self.tables() {
            now.set(timed.target, value(&timed.table));
        }
        now
    }

    /// Sets the load `target` (a table's) to `v`, its first entries as the load has them.
    fn set(&mut self, target: Target, v: [f64; 3]) {
        match (self, target) {
            (SceneLoads::Pendulum(l), _) => l.moment = v[0],
            (SceneLoads::Top(l), _) => l.moment_body = v,
            (SceneLoads::Planar(l), Target::ForceBody) => l.force_body = [v[0], v[1]],
            (SceneLoads::Planar(l), Target::ForceSpace) => l.force_space = [v[0], v[1]],
            (SceneLoads::Planar(l), _) => l.moment = v[0],
            (SceneLoads::Spatial(l), Target::ForceBody) => l.force_body = v,
            (SceneLoads::Spatial(l), Target::ForceSpace) => l.force_space = v,
            (SceneLoads::Spatial(l), Target::MomentSpace) => l.moment_space = v,
            (SceneLoads::Spatial(l), _) => l.moment_body = v,
        }
    }

    /// The loads as a run evaluates them, millions of times: which of them act is decided
    /// here, once, rather than by testing the scene's two dozen coefficients at every
    /// evaluation, and a free body's inputs are zeros that do not wait on its state (evaluating
    /// the scene's loads as they are, a free body's 10⁶-step RK4 scene run took 1.18–1.20 of
    /// the bare calls' time instead of 0.95: `cargo bench --bench driver`). A copy, so the
    /// decision cannot go stale.
    pub fn prepared(&self) -> PreparedLoads {
        PreparedLoads {
            loads: self.clone(),
            acting: self.acting(),
            timed: !self.tables().is_empty(),
            within: None,
        }
    }

    /// [`prepared`](Self::prepared) for the piece of a run from `a` to `b`, which no table
    /// time falls inside: each table is read as that piece's constant or line (see
    /// [`TimeTable::at_within`]), so that a step ending on a breakpoint sees the value
    /// before it.
    pub fn prepared_on(&self, a: f64, b: f64) -> PreparedLoads {
        PreparedLoads {
            within: Some((a, b)),
            ..self.prepared()
        }
    }

    /// Whether a spatial body has a load fixed in space, which its attitude turns.
    fn is_fixed_in_space(&self) -> bool {
        matches!(self, SceneLoads::Spatial(l) if l.is_fixed_in_space())
    }

    /// Which loads act.
    fn acting(&self) -> Acting {
        let (linear, quadratic): (&[f64], &[f64]) = match self {
            SceneLoads::Pendulum(l) => (
                std::slice::from_ref(&l.linear),
                std::slice::from_ref(&l.quadratic),
            ),
            SceneLoads::Top(l) => (&l.linear, &l.quadratic),
            SceneLoads::Planar(l) => (&l.linear, &l.quadratic),
            SceneLoads::Spatial(l) => (&l.linear, &l.quadratic),
        };
        Acting {
            any: !self.is_free(),
            damping: !all_zero(linear.iter().chain(quadratic)),
            in_space: self.is_fixed_in_space(),
        }
    }

    /// [`inputs`](Self::inputs) with which loads act already decided. One copy, called:
    /// inlined into every stage of every model's step it bought nothing measurable (the AUV
    /// scene with RK4 and 10⁶ steps).
    #[inline(never)]
    fn inputs_acting(&self, acting: Acting, state: &[f64], out: &mut [f64]) {
        match self {
            SceneLoads::Pendulum(l) => {
                out[0] = l.moment;
                let damping = (
                    std::slice::from_ref(&l.linear),
                    std::slice::from_ref(&l.quadratic),
                );
                add_damping(acting, damping, &state[1..2], &mut out[..1]);
            }
            SceneLoads::Top(l) => {
                out[..3].copy_from_slice(&l.moment_body);
                let damping = (&l.linear[..], &l.quadratic[..]);
                add_damping(acting, damping, &state[..3], &mut out[..3]);
            }
            SceneLoads::Planar(l) => l.inputs(acting, state, out),
            SceneLoads::Spatial(l) => l.inputs(acting, state, out),
        }
    }

    /// The potential energy of the loads at a state, where every load has one (zero for a
    /// free body); `None` where a load has none (body-axis forces, damping).
    pub fn potential_energy(&self, state: &[f64]) -> Option<f64> {
        match self {
            // The constant moment's potential is −M_O θ.
            SceneLoads::Pendulum(l) => l.is_conservative().then(|| -l.moment * state[0]),
            SceneLoads::Top(_) => self.is_free().then_some(0.0),
            SceneLoads::Planar(l) => l.potential_energy(state),
            SceneLoads::Spatial(l) => l.potential_energy(state),
        }
    }
}

impl PendulumLoads {
    /// No damping and no table: the moment, if any, has a potential.
    fn is_conservative(&self) -> bool {
        self.linear == 0.0 && self.quadratic == 0.0 && self.tables.is_empty()
    }
}

impl PlanarLoads {
    fn is_conservative(&self) -> bool {
        all_zero(
            self.force_body
                .iter()
                .chain(&self.linear)
                .chain(&self.quadratic),
        ) && self.tables.is_empty()
    }

    /// The heading and the body velocities (u, v, r), from either layout.
    fn heading_and_body_velocity(&self, state: &[f64]) -> (f64, [f64; 3]) {
        if self.space_fixed {
            let (s, c) = state[2].sin_cos();
            let (xd, yd) = (state[3], state[4]);
            (state[2], [c * xd + s * yd, -s * xd + c * yd, state[5]])
        } else {
            (state[5], [state[0], state[1], state[2]])
        }
    }

    fn inputs(&self, acting: Acting, state: &[f64], out: &mut [f64]) {
        let (psi, body) = self.heading_and_body_velocity(state);
        let (s, c) = psi.sin_cos();
        // Everything in body axes first, then turned into the model's axes.
        let (fs, fb) = (self.force_space, self.force_body);
        let fs_body = [c * fs[0] + s * fs[1], -s * fs[0] + c * fs[1]];
        let mut load = [fb[0] + fs_body[0], fb[1] + fs_body[1], self.moment];
        // A force at G adds no moment, and none is added, so that its zero keeps its sign.
        if self.force_body_at != [0.0; 2] {
            load[2] += lever_2d(self.force_body_at, fb);
        }
        if self.force_space_at != [0.0; 2] {
            load[2] += lever_2d(self.force_space_at, fs_body);
        }
        add_damping(acting, (&self.linear, &self.quadratic), &body, &mut load);
        let [fx, fy, moment] = load;
        if self.space_fixed {
            out[0] = c * fx - s * fy;
            out[1] = s * fx + c * fy;
        } else {
            out[0] = fx;
            out[1] = fy;
        }
        out[2] = moment;
    }

    fn potential_energy(&self, state: &[f64]) -> Option<f64> {
        let (x, y, psi) = if self.space_fixed {
            (state[0], state[1], state[2])
        } else {
            (state[3], state[4], state[5])
        };
        let (fs, r) = (self.force_space, self.force_space_at);
        // The force's point in space: G, and r_P turned by the heading.
        let (x, y) = if r == [0.0; 2] {
            (x, y)
        } else {
            let (s, c) = psi.sin_cos();
            (x + c * r[0] - s * r[1], y + s * r[0] + c * r[1])
        };
        self.is_conservative()
            .then(|| -fs[0] * x - fs[1] * y - self.moment * psi)
    }
}

impl SpatialLoads {
    fn from_table(table: &LoadsTable, selection: &Selection, mass: f64) -> Result<Self, LoadError> {
        let buoyancy = table.buoyancy.unwrap_or(0.0);
        let buoyancy = Requirement::NonNegative
            .check(buoyancy)
            .map_err(|violation| invalid("buoyancy", violation.to_string()))?;
        if table.buoyancy_centre.is_some() && table.buoyancy.is_none() {
            return Err(invalid(
                "buoyancy_centre",
                "is given without loads.buoyancy".into(),
            ));
        }
        let mut tables = Vec::new();
        let forces = Forces::<3>::read(table, &mut tables)?;
        Ok(SpatialLoads {
            kinematics: selection.info.kinematics.unwrap_or(Kinematics::Quaternion),
            weight: mass * scalar("gravity", table.gravity)?,
            buoyancy,
            buoyancy_centre: vector("buoyancy_centre", table.buoyancy_centre)?,
            force_body: forces.body,
            force_space: forces.space,
            force_body_at: forces.body_at,
            force_space_at: forces.space_at,
            moment_body: timed(
                "moment_body",
                &table.moment_body,
                (Target::MomentBody, &mut tables),
            )?,
            moment_space: timed(
                "moment_space",
                &table.moment_space,
                (Target::MomentSpace, &mut tables),
            )?,
            linear: damping("linear_damping", &table.linear_damping)?,
            quadratic: damping("quadratic_damping", &table.quadratic_damping)?,
            tables,
        })
    }

    /// Body-axis forces and moments, a space moment, damping and tables have no potential.
    fn is_conservative(&self) -> bool {
        all_zero(
            self.force_body
                .iter()
                .chain(&self.moment_body)
                .chain(&self.moment_space)
                .chain(&self.linear)
                .chain(&self.quadratic),
        ) && self.tables.is_empty()
    }

    /// Whether the weight is the only load: no buoyancy, no other force or moment, no damping.
    fn is_weight_alone(&self) -> bool {
        self.weight != 0.0
            && self.buoyancy == 0.0
            && self.is_conservative()
            && all_zero(&self.force_space)
    }

    /// Whether a load is fixed in space, so that the attitude turns it.
    fn is_fixed_in_space(&self) -> bool {
        self.weight != 0.0
            || self.buoyancy != 0.0
            || !all_zero(self.force_space.iter().chain(&self.moment_space))
            || self
                .tables
                .iter()
                .any(|timed| matches!(timed.target, Target::ForceSpace | Target::MomentSpace))
    }

    fn inputs(&self, acting: Acting, state: &[f64], out: &mut [f64]) {
        let mut force = Vector3::from(self.force_body);
        let mut moment = Vector3::from(self.moment_body);
        // A force at G adds no moment, and none is added, so that its zero keeps its sign.
        if self.force_body_at != [0.0; 3] {
            moment += Vector3::from(self.force_body_at).cross(&force);
        }
        // A scene without a load fixed in space skips the rotation.
        if acting.in_space {
            let to_body = attitude(self.kinematics, &state[9..]).inverse();
            let buoyancy_force = to_body * Vector3::new(0.0, 0.0, -self.buoyancy);
            let space_force = to_body * Vector3::from(self.force_space);
            force += space_force + to_body * Vector3::new(0.0, 0.0, self.weight) + buoyancy_force;
            moment += to_body * Vector3::from(self.moment_space)
                + Vector3::from(self.buoyancy_centre).cross(&buoyancy_force);
            if self.force_space_at != [0.0; 3] {
                moment += Vector3::from(self.force_space_at).cross(&space_force);
            }
        }
        out[..3].copy_from_slice(force.as_slice());
        out[3..6].copy_from_slice(moment.as_slice());
        add_damping(
            acting,
            (&self.linear, &self.quadratic),
            &state[..6],
            &mut out[..6],
        );
    }

    /// −M g z_G + B z_B − F·r_P, with Z down (r_P the space force's point, G unless the
    /// scene names another).
    fn potential_energy(&self, state: &[f64]) -> Option<f64> {
        let position = Vector3::new(state[6], state[7], state[8]);
        let to_space = attitude(self.kinematics, &state[9..]);
        let centre = position + to_space * Vector3::from(self.buoyancy_centre);
        let pushed = if self.force_space_at == [0.0; 3] {
            position
        } else {
            position + to_space * Vector3::from(self.force_space_at)
        };
        self.is_conservative().then(|| {
            -self.weight * position.z + self.buoyancy * centre.z
                - Vector3::from(self.force_space).dot(&pushed)
        })
    }
}

impl<const N: usize, const M: usize> Loads<f64, N, M> for SceneLoads {
    #[inline]
    fn at(&self, t: f64, state: &[f64; N]) -> [f64; M] {
        let mut out = [0.0; M];
        self.inputs_at(t, state, &mut out);
        out
    }
}

/// Which of a scene's loads act: decided from its constants.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Acting {
    /// Anything at all (a free body's inputs are all zero).
    any: bool,
    /// Some damping coefficient is not zero.
    damping: bool,
    /// A spatial body has a load fixed in space, which its attitude turns.
    in_space: bool,
}

/// A scene's loads with which of them act decided once ([`SceneLoads::prepared`]): the same
/// inputs as [`SceneLoads`] at every state, for a run's millions of evaluations.
#[derive(Debug, Clone, PartialEq)]
pub struct PreparedLoads {
    loads: SceneLoads,
    acting: Acting,
    /// Whether a load is a time table (decided once, as `acting`).
    timed: bool,
    /// The piece of the run its tables are read on ([`SceneLoads::prepared_on`]), or `None`
    /// to read them at each time.
    within: Option<(f64, f64)>,
}

impl PreparedLoads {
    /// The inputs where a load is a time table: every table read at `t`, on the piece.
    #[inline(never)]
    fn timed_inputs(&self, t: f64, state: &[f64], out: &mut [f64]) {
        let now = self.loads.with_tables_read(|table| match self.within {
            Some(piece) => table.at_within(t, piece),
            None => table.at(t),
        });
        now.inputs_acting(self.acting, state, out);
    }
}

impl<const N: usize, const M: usize> Loads<f64, N, M> for PreparedLoads {
    #[inline(always)]
    fn at(&self, t: f64, state: &[f64; N]) -> [f64; M] {
        let mut out = [0.0; M];
        if self.acting.any {
            if !self.timed {
                self.loads.inputs_acting(self.acting, state, &mut out);
            } else {
                self.timed_inputs(t, state, &mut out);
            }
        }
        out
    }
}
