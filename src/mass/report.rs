//! A body file's mass properties as `eom mass --json` prints them, for every caller that
//! reports them (the command, a binding): one shape, serialised by serde.

use super::{BodyFile, MassError, MassProperties};
use nalgebra::{Matrix3, Vector3};
use serde::Serialize;

/// One part of the body file, as read.
#[derive(Debug, Clone, Serialize)]
pub struct PartReport {
    /// Its number, from 1, in the order of the file.
    pub index: usize,
    /// Its name, if the file gives one.
    pub name: Option<String>,
    /// Its shape (`box`, `sphere`, `mesh`, …).
    pub kind: &'static str,
    /// Its mass, kg.
    pub mass: f64,
    /// Its centre of gravity in body axes, m.
    pub centre_of_gravity: [f64; 3],
}

/// The tensor about a point the caller names (4.23).
#[derive(Debug, Clone, Serialize)]
pub struct AboutReport {
    /// The point, in body axes, m.
    pub point: [f64; 3],
    /// The inertia tensor about it, kg m², rows.
    pub inertia: [[f64; 3]; 3],
}

/// The mass properties of a body file: what `eom mass` prints.
#[derive(Debug, Clone, Serialize)]
pub struct MassReport {
    /// M, kg.
    pub mass: f64,
    /// G in body axes, m.
    pub centre_of_gravity: [f64; 3],
    /// The inertia tensor about G (4.12; products Ixy = −∫xy dm, 4.14), rows, kg m².
    pub inertia_about_g: [[f64; 3]; 3],
    /// κxx, κyy, κzz about G (4.16–4.17), m.
    pub radii_of_gyration: [f64; 3],
    /// The principal moments about G, kg m².
    pub principal_moments: [f64; 3],
    /// The principal axes in body axes, one per row.
    pub principal_axes: [[f64; 3]; 3],
    /// The radii of gyration about the principal axes, m.
    pub principal_radii_of_gyration: [f64; 3],
    /// The tensor about the point asked for, if one was.
    pub about: Option<AboutReport>,
    /// Every part, in the order of the file.
    pub parts: Vec<PartReport>,
}

impl MassReport {
    /// The report of `body`, whose mass properties are `properties`, with the tensor about
    /// `about` (a point of the body axes) where one is asked for; a point that is not finite
    /// is an error.
    pub fn new(
        body: &BodyFile,
        properties: &MassProperties,
        about: Option<[f64; 3]>,
    ) -> Result<Self, MassError> {
        let about = match about {
            Some(point) => {
                let point = Vector3::from(point);
                let inertia = properties.inertia_about(&point)?;
                Some(AboutReport {
                    point: point.into(),
                    inertia: rows(&inertia.matrix()),
                })
            }
            None => None,
        };
        let principal = properties.principal();
        let parts = (body.parts().iter().enumerate())
            .map(|(i, part)| PartReport {
                index: i + 1,
                name: part.name.clone(),
                kind: part.kind,
                mass: part.mass,
                centre_of_gravity: part.centre_of_gravity.into(),
            })
            .collect();
        Ok(MassReport {
            mass: properties.mass(),
            centre_of_gravity: properties.centre_of_gravity().into(),
            inertia_about_g: rows(&properties.inertia().matrix()),
            radii_of_gyration: properties.radii_of_gyration().into(),
            principal_moments: principal.moments.into(),
            principal_axes: rows(&principal.axes.transpose()),
            principal_radii_of_gyration: principal.radii.into(),
            about,
            parts,
        })
    }
}

/// The rows of a matrix (for the principal axes, given the transpose: one axis per row).
fn rows(m: &Matrix3<f64>) -> [[f64; 3]; 3] {
    [0, 1, 2].map(|r| [0, 1, 2].map(|c| m[(r, c)]))
}
