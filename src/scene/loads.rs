//! What acts on a scene's body, as the inputs of its model.
//!
//! A model takes its inputs in its own axes (body axes about G for the spatial and body-fixed
//! planar models, space axes for the space-fixed planar model, a moment about the pivot for
//! the pendulum). A scene states loads where they are natural — gravity and buoyancy in space,
//! thrust in body axes, damping on the body velocities — and [`SceneLoads`] turns them into
//! the model's inputs at each state, through the attitude the state carries.
//!
//! Where every load has a potential (gravity, buoyancy, constant space forces, the
//! pendulum's and the planar body's constant moment), [`SceneLoads::potential_energy`] gives
//! it, so a run can report the total energy and its drift; body-axis forces and damping have
//! none.

use super::file::LoadsTable;
use super::{Body, Problem, Selection};
use crate::models::{Family, Kinematics, Loads};
use nalgebra::{Quaternion, Rotation3, UnitQuaternion, Vector3};

/// A scene's loads, by family.
#[derive(Debug, Clone, PartialEq)]
pub enum SceneLoads {
    /// The pendulum: a constant moment about the pivot and damping of θ̇ (gravity is in
    /// the model).
    Pendulum {
        /// Constant moment, N m.
        moment: f64,
        /// Linear damping coefficient.
        linear: f64,
        /// Quadratic damping coefficient.
        quadratic: f64,
        /// M g h, for the potential energy.
        mgh: f64,
    },
    /// A planar body.
    Planar {
        /// Whether the model's state is space-fixed (4.39) rather than body-fixed.
        space_fixed: bool,
        /// Constant force, body axes.
        force_body: [f64; 2],
        /// Constant force, space axes.
        force_space: [f64; 2],
        /// Constant moment about the vertical.
        moment: f64,
        /// Linear damping of (u, v, r).
        linear: [f64; 3],
        /// Quadratic damping of (u, v, r).
        quadratic: [f64; 3],
    },
    /// A heavy top: a constant moment about the pivot in body axes and damping of (p, q, r)
    /// (gravity is in the model).
    Top {
        /// Constant moment, body axes.
        moment_body: [f64; 3],
        /// Linear damping of (p, q, r).
        linear: [f64; 3],
        /// Quadratic damping of (p, q, r).
        quadratic: [f64; 3],
    },
    /// A spatial body.
    Spatial {
        /// Euler angles or a quaternion in the state.
        kinematics: Kinematics,
        /// The weight M g, N, along +Z.
        weight: f64,
        /// The buoyancy B, N, along −Z.
        buoyancy: f64,
        /// The centre of buoyancy relative to G, body axes.
        buoyancy_centre: [f64; 3],
        /// Constant force, body axes.
        force_body: [f64; 3],
        /// Constant force, space axes.
        force_space: [f64; 3],
        /// Constant moment, body axes.
        moment_body: [f64; 3],
        /// Constant moment, space axes.
        moment_space: [f64; 3],
        /// Linear damping of (u, v, w, p, q, r).
        linear: [f64; 6],
        /// Quadratic damping of (u, v, w, p, q, r).
        quadratic: [f64; 6],
    },
}

type LoadError = (String, Problem);

fn invalid(key: &str, message: String) -> LoadError {
    (format!("loads.{key}"), Problem::Invalid(message))
}

/// Every entry finite; the key path names the first that is not.
fn finite<const K: usize>(key: &str, values: [f64; K]) -> Result<[f64; K], LoadError> {
    match values.iter().position(|v| !v.is_finite()) {
        None => Ok(values),
        Some(i) => Err(invalid(
            &format!("{key}[{i}]"),
            format!("must be finite, got {}", values[i]),
        )),
    }
}

fn scalar(key: &str, value: Option<f64>) -> Result<f64, LoadError> {
    Ok(finite(key, [value.unwrap_or(0.0)])?[0])
}

/// A list of exactly `K` entries (zeros when absent).
fn list<const K: usize>(key: &str, values: &Option<Vec<f64>>) -> Result<[f64; K], LoadError> {
    let Some(values) = values else {
        return Ok([0.0; K]);
    };
    let array: [f64; K] = values
        .as_slice()
        .try_into()
        .map_err(|_| invalid(key, format!("must have {K} entries, got {}", values.len())))?;
    finite(key, array)
}

/// Damping coefficients: finite and not negative (a negative one would feed energy in).
fn damping<const K: usize>(key: &str, values: &Option<Vec<f64>>) -> Result<[f64; K], LoadError> {
    let d = list::<K>(key, values)?;
    match d.iter().position(|x| *x < 0.0) {
        None => Ok(d),
        Some(i) => Err(invalid(
            &format!("{key}[{i}]"),
            format!("must not be negative, got {}", d[i]),
        )),
    }
}

impl SceneLoads {
    /// The loads of a scene's `[loads]` table for the selected model and body.
    pub(crate) fn from_table(
        table: &LoadsTable,
        selection: &Selection,
        body: &Body,
    ) -> Result<Self, LoadError> {
        Ok(match (selection.info.family, body) {
            (Family::Pendulum, Body::Pendulum(p)) => SceneLoads::Pendulum {
                moment: scalar("moment", table.moment)?,
                linear: damping::<1>("linear_damping", &table.linear_damping)?[0],
                quadratic: damping::<1>("quadratic_damping", &table.quadratic_damping)?[0],
                mgh: p.restoring_moment(),
            },
            (
                family @ (Family::PlanarAtG | Family::PlanarMidship | Family::PlanarSpaceFixed),
                _,
            ) => SceneLoads::Planar {
                space_fixed: family == Family::PlanarSpaceFixed,
                force_body: list("force_body", &table.force_body)?,
                force_space: list("force_space", &table.force_space)?,
                moment: scalar("moment", table.moment)?,
                linear: damping("linear_damping", &table.linear_damping)?,
                quadratic: damping("quadratic_damping", &table.quadratic_damping)?,
            },
            (Family::Top, _) => SceneLoads::Top {
                moment_body: finite("moment_body", table.moment_body.unwrap_or([0.0; 3]))?,
                linear: damping("linear_damping", &table.linear_damping)?,
                quadratic: damping("quadratic_damping", &table.quadratic_damping)?,
            },
            (_, Body::Spatial { mass, .. }) => {
                let gravity = scalar("gravity", table.gravity)?;
                let buoyancy = scalar("buoyancy", table.buoyancy)?;
                if buoyancy < 0.0 {
                    return Err(invalid(
                        "buoyancy",
                        format!("must not be negative, got {buoyancy}"),
                    ));
                }
                if table.buoyancy_centre.is_some() && table.buoyancy.is_none() {
                    return Err(invalid(
                        "buoyancy_centre",
                        "is given without loads.buoyancy".into(),
                    ));
                }
                SceneLoads::Spatial {
                    kinematics: selection.info.kinematics.unwrap_or(Kinematics::Quaternion),
                    weight: mass * gravity,
                    buoyancy,
                    buoyancy_centre: finite(
                        "buoyancy_centre",
                        table.buoyancy_centre.unwrap_or([0.0; 3]),
                    )?,
                    force_body: list("force_body", &table.force_body)?,
                    force_space: list("force_space", &table.force_space)?,
                    moment_body: finite("moment_body", table.moment_body.unwrap_or([0.0; 3]))?,
                    moment_space: finite("moment_space", table.moment_space.unwrap_or([0.0; 3]))?,
                    linear: damping("linear_damping", &table.linear_damping)?,
                    quadratic: damping("quadratic_damping", &table.quadratic_damping)?,
                }
            }
            (family, _) => unreachable!("the body of a {} scene matches its family", family.name()),
        })
    }

    /// True when nothing acts on the body at all.
    pub fn is_free(&self) -> bool {
        match self {
            SceneLoads::Pendulum { .. } | SceneLoads::Top { .. } => false,
            SceneLoads::Planar {
                force_body,
                force_space,
                moment,
                linear,
                quadratic,
                ..
            } => [
                force_body.as_slice(),
                force_space,
                &[*moment],
                linear,
                quadratic,
            ]
            .concat()
            .iter()
            .all(|x| *x == 0.0),
            SceneLoads::Spatial {
                weight,
                buoyancy,
                force_body,
                force_space,
                moment_body,
                moment_space,
                linear,
                quadratic,
                ..
            } => [
                &[*weight, *buoyancy][..],
                force_body,
                force_space,
                moment_body,
                moment_space,
                linear,
                quadratic,
            ]
            .concat()
            .iter()
            .all(|x| *x == 0.0),
        }
    }

    /// The inputs of the model at a state, into `out` (the model's input layout).
    pub fn inputs(&self, state: &[f64], out: &mut [f64]) {
        match self {
            SceneLoads::Pendulum {
                moment,
                linear,
                quadratic,
                ..
            } => {
                let rate = state[1];
                out[0] = moment - linear * rate - quadratic * rate * rate.abs();
            }
            SceneLoads::Top {
                moment_body,
                linear,
                quadratic,
            } => {
                for i in 0..3 {
                    let w = state[i];
                    out[i] = moment_body[i] - linear[i] * w - quadratic[i] * w * w.abs();
                }
            }
            SceneLoads::Planar { .. } => self.planar_inputs(state, out),
            SceneLoads::Spatial { .. } => self.spatial_inputs(state, out),
        }
    }

    fn planar_inputs(&self, state: &[f64], out: &mut [f64]) {
        let SceneLoads::Planar {
            space_fixed,
            force_body,
            force_space,
            moment,
            linear,
            quadratic,
        } = self
        else {
            unreachable!()
        };
        // Body velocities (u, v, r) and the heading, from either layout.
        let (psi, body) = if *space_fixed {
            let (s, c) = state[2].sin_cos();
            let (xd, yd) = (state[3], state[4]);
            (state[2], [c * xd + s * yd, -s * xd + c * yd, state[5]])
        } else {
            (state[5], [state[0], state[1], state[2]])
        };
        let (s, c) = psi.sin_cos();
        let damped: [f64; 3] =
            std::array::from_fn(|i| -linear[i] * body[i] - quadratic[i] * body[i] * body[i].abs());
        // Everything in body axes first, then turned into the model's axes.
        let fx = force_body[0] + c * force_space[0] + s * force_space[1] + damped[0];
        let fy = force_body[1] - s * force_space[0] + c * force_space[1] + damped[1];
        let n = moment + damped[2];
        if *space_fixed {
            out[0] = c * fx - s * fy;
            out[1] = s * fx + c * fy;
        } else {
            out[0] = fx;
            out[1] = fy;
        }
        out[2] = n;
    }

    fn spatial_inputs(&self, state: &[f64], out: &mut [f64]) {
        let SceneLoads::Spatial {
            kinematics,
            weight,
            buoyancy,
            buoyancy_centre,
            force_body,
            force_space,
            moment_body,
            moment_space,
            linear,
            quadratic,
        } = self
        else {
            unreachable!()
        };
        let mut force = Vector3::from(*force_body);
        let mut moment = Vector3::from(*moment_body);
        let in_space = *weight != 0.0
            || *buoyancy != 0.0
            || force_space.iter().chain(moment_space).any(|x| *x != 0.0);
        // Loads fixed in space are turned into body axes through the attitude; a scene
        // without any skips the rotation.
        if in_space {
            let to_body = attitude(*kinematics, &state[9..]).inverse();
            let buoyancy_force = to_body * Vector3::new(0.0, 0.0, -buoyancy);
            force += to_body * Vector3::from(*force_space)
                + to_body * Vector3::new(0.0, 0.0, *weight)
                + buoyancy_force;
            moment += to_body * Vector3::from(*moment_space)
                + Vector3::from(*buoyancy_centre).cross(&buoyancy_force);
        }
        for i in 0..3 {
            let (v, w) = (state[i], state[3 + i]);
            out[i] = force[i] - linear[i] * v - quadratic[i] * v * v.abs();
            out[3 + i] = moment[i] - linear[3 + i] * w - quadratic[3 + i] * w * w.abs();
        }
    }

    /// Whether a load with a potential is present, so that a trajectory has potential and
    /// total energy columns (a free body's potential is zero, and has none).
    pub fn has_potential(&self) -> bool {
        let zero = vec![0.0; 13];
        self.potential_energy(&zero).is_some() && !self.is_free_of_potential()
    }

    fn is_free_of_potential(&self) -> bool {
        match self {
            SceneLoads::Pendulum { moment, .. } => *moment == 0.0,
            SceneLoads::Top { .. } => true,
            SceneLoads::Planar {
                force_space,
                moment,
                ..
            } => force_space.iter().all(|x| *x == 0.0) && *moment == 0.0,
            SceneLoads::Spatial {
                weight,
                buoyancy,
                force_space,
                ..
            } => *weight == 0.0 && *buoyancy == 0.0 && force_space.iter().all(|x| *x == 0.0),
        }
    }

    /// The potential energy of the loads at a state, where every load has one (zero for a
    /// free body); `None` where a load has none (body-axis forces, damping).
    pub fn potential_energy(&self, state: &[f64]) -> Option<f64> {
        match self {
            SceneLoads::Pendulum {
                moment,
                linear,
                quadratic,
                ..
            } => {
                // Gravity is the model's own potential (4.35); the constant moment's is −M_O θ.
                let conservative = *linear == 0.0 && *quadratic == 0.0;
                conservative.then(|| -moment * state[0])
            }
            SceneLoads::Top {
                moment_body,
                linear,
                quadratic,
            } => moment_body
                .iter()
                .chain(linear)
                .chain(quadratic)
                .all(|x| *x == 0.0)
                .then_some(0.0),
            SceneLoads::Planar {
                space_fixed,
                force_body,
                force_space,
                moment,
                linear,
                quadratic,
            } => {
                let conservative = force_body
                    .iter()
                    .chain(linear)
                    .chain(quadratic)
                    .all(|x| *x == 0.0);
                let (x, y, psi) = if *space_fixed {
                    (state[0], state[1], state[2])
                } else {
                    (state[3], state[4], state[5])
                };
                conservative.then(|| -force_space[0] * x - force_space[1] * y - moment * psi)
            }
            SceneLoads::Spatial {
                kinematics,
                weight,
                buoyancy,
                buoyancy_centre,
                force_body,
                force_space,
                moment_body,
                moment_space,
                linear,
                quadratic,
            } => {
                let conservative = force_body
                    .iter()
                    .chain(moment_body)
                    .chain(moment_space)
                    .chain(linear)
                    .chain(quadratic)
                    .all(|x| *x == 0.0);
                let position = Vector3::new(state[6], state[7], state[8]);
                let centre =
                    position + attitude(*kinematics, state) * Vector3::from(*buoyancy_centre);
                conservative.then(|| {
                    -weight * position.z + buoyancy * centre.z
                        - Vector3::from(*force_space).dot(&position)
                })
            }
        }
    }
}

/// The rotation from body to space axes of an attitude, `[φ, θ, ψ]` (E of 4.57) or
/// `[q0, q1, q2, q3]` (normalised).
pub(crate) fn attitude(kinematics: Kinematics, a: &[f64]) -> Rotation3<f64> {
    match kinematics {
        Kinematics::Euler => Rotation3::from_euler_angles(a[0], a[1], a[2]),
        Kinematics::Quaternion => {
            let q = Quaternion::new(a[0], a[1], a[2], a[3]);
            UnitQuaternion::from_quaternion(q).to_rotation_matrix()
        }
    }
}

/// Roll, pitch and yaw, radians, of an attitude as the model carries it (the state from its
/// attitude entries on: index 9 of a spatial state, 3 of a top's).
pub fn euler_angles(kinematics: Kinematics, attitude_entries: &[f64]) -> [f64; 3] {
    match kinematics {
        Kinematics::Euler => [
            attitude_entries[0],
            attitude_entries[1],
            attitude_entries[2],
        ],
        Kinematics::Quaternion => {
            let (r, p, y) = attitude(kinematics, attitude_entries).euler_angles();
            [r, p, y]
        }
    }
}

impl<const N: usize, const M: usize> Loads<f64, N, M> for SceneLoads {
    #[inline]
    fn at(&self, _t: f64, state: &[f64; N]) -> [f64; M] {
        let mut out = [0.0; M];
        self.inputs(state, &mut out);
        out
    }
}
