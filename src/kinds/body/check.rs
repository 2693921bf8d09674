//! The checks of a catalog body's scene, family by family: each key a key of the scene's
//! family, the body's mass properties, the model they select able to run, the initial state,
//! the integrator over the run and where the run may stop — every error naming its key by its
//! path in the file (`initial.rates`). The checks every scene shares are
//! [`crate::scene`]'s, methods of the same `Checker`.

use super::file::{self, GivenKeys, SceneFile};
use super::{Body, IntegratorSpec, SceneLoads, Selection, select_spatial};
use crate::Short;
use crate::models::{AnyModel, Family, Kinematics, ModelInfo, Symmetry};
use crate::scene::check::{Checker, MethodKeys};
use crate::scene::reference;
use crate::scene::{DEFAULT_ROWS, MAX_ROWS, Method, Problem, SceneError, StopCondition};
use crate::validate::Requirement;
use crate::{InertiaTensor, PendulumParameters};
use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};
use std::path::Path;

/// A planar body's initial velocity of G in body axes (u, v) and in space axes (Ẋ, Ẏ).
struct PlanarVelocity {
    body: [f64; 2],
    space: [f64; 2],
}

impl Checker<'_> {
    pub(super) fn family(&self, name: &str) -> Result<Family, SceneError> {
        Family::ALL
            .into_iter()
            .find(|f| f.name() == name)
            .ok_or_else(|| {
                let names: Vec<&str> = Family::ALL.iter().map(|f| f.name()).collect();
                self.invalid(
                    "model.family",
                    format!("unknown family `{name}`; one of {}", names.join(", ")),
                )
            })
    }

    /// Refuses a key that another family reads: it would be ignored, silently. What each
    /// family reads in each table is the scene reference's ([`reference::table_keys`]).
    pub(super) fn keys_of_family(
        &self,
        file: &SceneFile,
        family: Family,
    ) -> Result<(), SceneError> {
        let tables = [
            ("body", file.body.given()),
            ("model", file.model.given()),
            ("initial", file.initial.given()),
            ("loads", file.loads.given()),
        ];
        for (table, given) in tables {
            let allowed = reference::table_keys(family, table);
            if let Some(key) = given.iter().find(|k| !allowed.contains(k)) {
                return Err(self.error(
                    &format!("{table}.{key}"),
                    Problem::Schema(format!(
                        "not a key of a {} scene; its [{table}] takes {}",
                        family.name(),
                        allowed.join(", ")
                    )),
                ));
            }
        }
        Ok(())
    }

    /// The tensor about G of `body.inertia`, a physical one.
    fn tensor(&self, rows: Option<[[f64; 3]; 3]>, what: &str) -> Result<InertiaTensor, SceneError> {
        let rows = rows.ok_or_else(|| self.missing("body.inertia", what))?;
        InertiaTensor::from_matrix(Matrix3::from_fn(|r, c| rows[r][c]))
            .map_err(|e| self.invalid("body.inertia", e.to_string()))
    }

    pub(super) fn body(
        &self,
        file: &SceneFile,
        family: Family,
        base: &Path,
    ) -> Result<Body, SceneError> {
        let b = &file.body;
        match family {
            Family::Pendulum => {
                let i0 = self.required("body.i0", b.i0, "I₀ about the pivot, kg m²")?;
                let mass = self.required("body.mass", b.mass, "the mass, kg")?;
                let g = self.required("body.g", b.g, "gravity, m/s²")?;
                let h = self.required("body.h", b.h, "the pivot-to-G distance, m")?;
                PendulumParameters::new(i0, mass, g, h)
                    .map(Body::Pendulum)
                    .map_err(|e| self.invalid(&format!("body.{}", e.field), e.to_string()))
            }
            Family::PlanarAtG | Family::PlanarMidship | Family::PlanarSpaceFixed => {
                let mass = self.required("body.mass", b.mass, "the mass, kg")?;
                let izz = self.required("body.izz", b.izz, "I_zz about G, kg m²")?;
                let mass =
                    self.parameter("body.mass", || crate::validate::positive("mass", mass))?;
                let izz = self.parameter("body.izz", || crate::validate::positive("izz", izz))?;
                let x_g = match family {
                    Family::PlanarMidship => {
                        let x_g = self.required("body.x_g", b.x_g, "G ahead of midship, m")?;
                        Some(self.parameter("body.x_g", || crate::validate::finite("x_g", x_g))?)
                    }
                    _ => None,
                };
                Ok(Body::Planar { mass, izz, x_g })
            }
            Family::Spatial => self.spatial_body(b, base),
            Family::Top => self.top_body(b),
        }
    }

    fn top_body(&self, b: &file::BodyTable) -> Result<Body, SceneError> {
        let mass = self.required("body.mass", b.mass, "the mass, kg")?;
        let inertia = self.tensor(b.inertia, "the principal tensor about G, kg m²")?;
        let h = self.required("body.h", b.h, "pivot to G along the body z-axis, m")?;
        let g = self.required("body.g", b.g, "gravity, m/s²")?;
        // Both kinematics check the same parameters; building one is the check.
        AnyModel::top(Kinematics::Quaternion, mass, &inertia, h, g).map_err(|e| {
            let key = match &e {
                crate::generic::ModelError::Parameter(p) => format!("body.{}", p.field),
                _ => "body.inertia".to_owned(),
            };
            self.invalid(&key, e.to_string())
        })?;
        Ok(Body::Top {
            mass,
            inertia,
            h,
            g,
        })
    }

    fn spatial_body(&self, b: &file::BodyTable, base: &Path) -> Result<Body, SceneError> {
        if let Some(path) = &b.file {
            self.refuse_given(
                [
                    ("body.mass", b.mass.is_some()),
                    ("body.inertia", b.inertia.is_some()),
                ],
                "give either body.file or body.mass and body.inertia, not both",
            )?;
            let description = crate::mass::BodyFile::load(&base.join(path))
                .map_err(|e| self.error("body.file", Problem::BodyFile(Box::new(e))))?;
            let properties = description
                .mass_properties()
                .map_err(|e| self.error("body.file", Problem::BodyFile(Box::new(e))))?;
            return Ok(Body::Spatial {
                mass: properties.mass(),
                inertia: properties.inertia(),
            });
        }
        let mass = self.required("body.mass", b.mass, "the mass, kg (or body.file)")?;
        let mass = self.parameter("body.mass", || crate::validate::positive("mass", mass))?;
        let inertia = self.tensor(
            b.inertia,
            "the tensor about G, [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]] (or body.file)",
        )?;
        Ok(Body::Spatial { mass, inertia })
    }

    pub(super) fn selection(
        &self,
        file: &SceneFile,
        family: Family,
        body: &Body,
    ) -> Result<Selection, SceneError> {
        if family == Family::Top {
            let kinematics = self.kinematics(file)?;
            let info = ModelInfo::of_family(family)
                .find(|i| i.kinematics == Some(kinematics))
                .expect("the catalog has a top of each kinematics");
            return Ok(Selection {
                info,
                reason: format!(
                    "a top with {} kinematics, as the scene says",
                    kinematics.name()
                ),
            });
        }
        let Body::Spatial { mass, inertia } = body else {
            let info = ModelInfo::of_family(family)
                .next()
                .expect("every family has a model");
            return Ok(Selection::only(info));
        };
        let symmetry = match file.model.symmetry.as_deref() {
            None | Some("auto") => None,
            Some(name) => Some(self.named(
                "model.symmetry",
                name,
                Symmetry::ALL.map(|s| (s, s.name())),
                "auto",
            )?),
        };
        let kinematics = self.kinematics(file)?;
        let selection = select_spatial(inertia, symmetry, kinematics)
            .map_err(|message| self.invalid("model.symmetry", message))?;
        // The model checks more than a valid tensor promises (a determinant that f64 can
        // invert, 1e-110 kg m² on the diagonal is not): a scene accepted builds its model.
        let symmetry = selection
            .info
            .symmetry
            .expect("a spatial model has a symmetry class");
        AnyModel::spatial(symmetry, kinematics, *mass, inertia).map_err(|e| {
            let key = if file.body.file.is_some() {
                "body.file"
            } else {
                match e {
                    crate::generic::ModelError::Parameter(_) => "body.mass",
                    _ => "body.inertia",
                }
            };
            self.invalid(key, e.to_string())
        })?;
        Ok(selection)
    }

    /// `model.kinematics`, quaternion when the scene leaves it out.
    fn kinematics(&self, file: &SceneFile) -> Result<Kinematics, SceneError> {
        match file.model.kinematics.as_deref() {
            None => Ok(Kinematics::Quaternion),
            Some(name) => self.named(
                "model.kinematics",
                name,
                Kinematics::ALL.map(|k| (k, k.name())),
                "",
            ),
        }
    }

    pub(super) fn initial(
        &self,
        file: &SceneFile,
        selection: &Selection,
    ) -> Result<Vec<f64>, SceneError> {
        let i = &file.initial;
        let scalar =
            |key: &str, v: Option<f64>| self.finite(&format!("initial.{key}"), v.unwrap_or(0.0));
        Ok(match selection.info.family {
            Family::Pendulum => vec![
                scalar("theta_deg", i.theta_deg)?.to_radians(),
                scalar("theta_dot", i.theta_dot)?,
            ],
            Family::PlanarAtG | Family::PlanarMidship => {
                let psi = scalar("psi_deg", i.psi_deg)?.to_radians();
                let [u, v] = self.planar_velocity(i, psi)?.body;
                vec![
                    u,
                    v,
                    scalar("r", i.r)?,
                    scalar("x", i.x)?,
                    scalar("y", i.y)?,
                    psi,
                ]
            }
            Family::PlanarSpaceFixed => {
                let psi = scalar("psi_deg", i.psi_deg)?.to_radians();
                let [x_dot, y_dot] = self.planar_velocity(i, psi)?.space;
                vec![
                    scalar("x", i.x)?,
                    scalar("y", i.y)?,
                    psi,
                    x_dot,
                    y_dot,
                    scalar("r", i.r)?,
                ]
            }
            Family::Spatial => {
                let mut state = Vec::with_capacity(13);
                state.extend(self.spatial_velocity(i)?);
                state.extend(self.finite3("initial.rates", i.rates)?);
                state.extend(self.finite3("initial.position", i.position)?);
                state.extend(self.attitude(i, selection)?);
                state
            }
            Family::Top => {
                let mut state = Vec::with_capacity(7);
                state.extend(self.finite3("initial.rates", i.rates)?);
                state.extend(self.attitude(i, selection)?);
                state
            }
        })
    }

    /// The body velocity of G, (u, v, w): `initial.velocity` as given, or
    /// `initial.velocity_space` turned into body axes by the attitude, v = Rᵀ V (R from body
    /// to space axes, 4.56); never both.
    fn spatial_velocity(&self, i: &file::InitialTable) -> Result<[f64; 3], SceneError> {
        let Some(space) = i.velocity_space else {
            return self.finite3("initial.velocity", i.velocity);
        };
        if i.velocity.is_some() {
            return Err(self.invalid(
                "initial.velocity_space",
                "give the velocity of G in body axes (initial.velocity) or in space axes \
                 (initial.velocity_space), not both",
            ));
        }
        let space = self.finite3("initial.velocity_space", Some(space))?;
        let [roll, pitch, yaw] = self
            .finite3("initial.attitude_deg", i.attitude_deg)?
            .map(f64::to_radians);
        let to_space = Rotation3::from_euler_angles(roll, pitch, yaw);
        let body = to_space.transpose() * Vector3::from(space);
        Ok([body.x, body.y, body.z])
    }

    /// A planar body's velocity of G in both axes: `initial.u`, `initial.v` in body axes, or
    /// `initial.x_dot`, `initial.y_dot` in space axes, turned by the heading ψ; never both.
    fn planar_velocity(
        &self,
        i: &file::InitialTable,
        psi: f64,
    ) -> Result<PlanarVelocity, SceneError> {
        let scalar =
            |key: &str, v: Option<f64>| self.finite(&format!("initial.{key}"), v.unwrap_or(0.0));
        let (s, c) = psi.sin_cos();
        let in_space = i.x_dot.is_some() || i.y_dot.is_some();
        if !in_space {
            let (u, v) = (scalar("u", i.u)?, scalar("v", i.v)?);
            return Ok(PlanarVelocity {
                body: [u, v],
                space: [u * c - v * s, u * s + v * c],
            });
        }
        if i.u.is_some() || i.v.is_some() {
            let body = if i.u.is_some() { "u" } else { "v" };
            let space = if i.x_dot.is_some() { "x_dot" } else { "y_dot" };
            return Err(self.invalid(
                &format!("initial.{space}"),
                format!(
                    "give the velocity of G in body axes (initial.u, initial.v) or in space \
                     axes (initial.x_dot, initial.y_dot), not both: initial.{body} is given too"
                ),
            ));
        }
        let (x_dot, y_dot) = (scalar("x_dot", i.x_dot)?, scalar("y_dot", i.y_dot)?);
        Ok(PlanarVelocity {
            body: [c * x_dot + s * y_dot, -s * x_dot + c * y_dot],
            space: [x_dot, y_dot],
        })
    }

    /// `initial.attitude_deg` as the model carries it: Euler angles or a quaternion.
    fn attitude(
        &self,
        i: &file::InitialTable,
        selection: &Selection,
    ) -> Result<Vec<f64>, SceneError> {
        let [roll, pitch, yaw] = self
            .finite3("initial.attitude_deg", i.attitude_deg)?
            .map(f64::to_radians);
        Ok(match selection.info.kinematics {
            Some(Kinematics::Euler) => vec![roll, pitch, yaw],
            _ => {
                let q = UnitQuaternion::from_euler_angles(roll, pitch, yaw);
                vec![q.w, q.i, q.j, q.k]
            }
        })
    }

    pub(super) fn integrator(
        &self,
        file: &SceneFile,
        loads: &SceneLoads,
    ) -> Result<IntegratorSpec, SceneError> {
        let t = &file.integrator;
        let end_time = self.checked("integrator.end_time", Requirement::Positive, t.end_time)?;
        let keys = MethodKeys {
            method: &t.method,
            step: t.step,
            rtol: t.rtol,
            atol: t.atol,
            max_steps: t.max_steps,
        };
        let settings = self.method_settings(&keys, end_time)?;
        if settings.method == Method::LieMidpoint {
            self.lie_midpoint_applies(loads)?;
        }
        Ok(IntegratorSpec {
            method: settings.method,
            step: settings.step,
            adaptive: settings.adaptive,
            end_time,
            max_steps: settings.max_steps,
        })
    }

    /// The geometric integrator turns a body's attitude and rates (`RigidRotation`) where no
    /// moment acts about G: a free body, or one under uniform gravity at G alone; its
    /// translation is then exact (constant velocity, or free fall).
    fn lie_midpoint_applies(&self, loads: &SceneLoads) -> Result<(), SceneError> {
        if loads.rotation_is_torque_free() {
            Ok(())
        } else {
            Err(self.invalid(
                "integrator.method",
                "lie-midpoint integrates a rotation free of moments about G: a spatial scene \
                 with quaternion kinematics and no loads but loads.gravity",
            ))
        }
    }

    /// `integrator.stop_when`, read against the model's state names; a condition that holds
    /// at the start would end the run before it begins, and is refused.
    pub(super) fn stop(
        &self,
        file: &SceneFile,
        selection: &Selection,
        initial: &[f64],
    ) -> Result<Option<StopCondition>, SceneError> {
        let names: Vec<String> = (selection.info.state.iter())
            .map(|name| name.to_lowercase())
            .collect();
        let starts = [(String::new(), initial)];
        self.stop_when(file.integrator.stop_when.as_deref(), &names, starts)
    }

    pub(super) fn every(&self, file: &SceneFile, end_time: f64) -> Result<f64, SceneError> {
        let Some(every) = file.output.every else {
            // An end time within 500 of the smallest f64 would give rows 0 s apart.
            let every = end_time / DEFAULT_ROWS;
            return if every > 0.0 {
                Ok(every)
            } else {
                Err(self.invalid(
                    "integrator.end_time",
                    format!(
                        "{} s is too short to divide into {DEFAULT_ROWS} rows",
                        Short(end_time)
                    ),
                ))
            };
        };
        let every = self.finite("output.every", every)?;
        if every <= 0.0 || every > end_time {
            return Err(self.invalid(
                "output.every",
                format!(
                    "must be positive and at most integrator.end_time = {}, got {}",
                    Short(end_time),
                    Short(every)
                ),
            ));
        }
        if end_time / every > MAX_ROWS as f64 {
            return Err(self.invalid(
                "output.every",
                format!(
                    "gives {} rows over integrator.end_time = {}, more than {}; a longer every \
                     keeps the file readable",
                    Short(end_time / every),
                    Short(end_time),
                    Short(MAX_ROWS as f64)
                ),
            ));
        }
        Ok(every)
    }
}
