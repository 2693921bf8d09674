//! The body file read by `eom mass`: a TOML list of parts (primitives, point masses, meshes),
//! each placed in body axes.
//!
//! ```toml
//! [[part]]
//! name = "hull"                  # optional, for messages
//! kind = "box"                   # box | sphere | ellipsoid | cylinder | hollow_cylinder | point | mesh
//! mass = 1200.0
//! size = [10.0, 2.0, 2.0]        # L, B, D
//! offset = [0.0, 0.0, -0.5]      # where the part's own origin (its G, for a primitive) goes
//! rotation_deg = [0.0, 0.0, 0.0] # roll, pitch, yaw: E = Rz(ψ) Ry(θ) Rx(φ) as in 4.57
//! ```
//!
//! Parts are numbered from 1 in the order they appear; an unknown key, a missing key and a key
//! that does not belong to the part's kind are errors naming the part and the key. A mesh's
//! `path` is relative to the body file's folder.

use super::composite::Composite;
use super::error::MassError;
use super::mesh::{Mesh, MeshError, MeshMass};
use super::primitives::{ellipsoid, hollow_cylinder, solid_box, solid_cylinder, sphere};
use super::properties::{MassProperties, rotation_from_degrees};
use nalgebra::Vector3;
use serde::Deserialize;
use std::path::{Path, PathBuf};
use thiserror::Error;

/// Why a body file cannot be turned into mass properties.
#[derive(Debug, Error)]
pub enum BodyFileError {
    /// The file could not be read.
    #[error("cannot read body file {path}: {error}")]
    Read {
        /// The file.
        path: PathBuf,
        /// What the system said.
        error: std::io::Error,
    },
    /// The file is not valid TOML, or has an unknown top-level key.
    #[error("body file: {0}")]
    Syntax(toml::de::Error),
    /// The file has no `[[part]]`.
    #[error("body file has no [[part]]")]
    NoParts,
    /// One part is wrong.
    #[error("part {index}{label}: {error}")]
    Part {
        /// The part's number, from 1, in the order of the file.
        index: usize,
        /// ` ("name")` if the part has a name, else empty.
        label: String,
        /// What is wrong with it (boxed: TOML errors are large, and errors are rare).
        error: Box<PartError>,
    },
    /// Every part is valid but together they are not a rigid body (for instance, point masses
    /// on one line).
    #[error("the parts together: {0}")]
    Combination(MassError),
}

/// What is wrong with one part.
#[derive(Debug, Error)]
pub enum PartError {
    /// An unknown key, a key of the wrong type, or an unknown kind.
    #[error("{}", one_line(.0))]
    Field(toml::de::Error),
    /// A key that this kind needs is missing.
    #[error("a {kind} needs `{field}`")]
    Missing {
        /// The part's kind.
        kind: &'static str,
        /// The missing key.
        field: &'static str,
    },
    /// A key that means nothing for this kind.
    #[error("`{field}` does not apply to a {kind}")]
    NotApplicable {
        /// The part's kind.
        kind: &'static str,
        /// The key given.
        field: &'static str,
    },
    /// A mesh was given both `mass` and `density`, or neither.
    #[error("a mesh needs exactly one of `mass` and `density`")]
    MassOrDensity,
    /// A value is not physical.
    #[error(transparent)]
    Mass(#[from] MassError),
    /// The mesh file is not a closed, oriented solid.
    #[error("mesh {path}: {error}")]
    Mesh {
        /// The STL file.
        path: PathBuf,
        /// What is wrong with it.
        error: MeshError,
    },
}

/// serde's messages name the key on a line of their own (`…\nin `mass``); one line reads
/// better after "part 2: ".
fn one_line(error: &toml::de::Error) -> String {
    error.to_string().trim().replace('\n', " ")
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFile {
    #[serde(default)]
    part: Vec<toml::Value>,
}

#[derive(Deserialize, Clone, Copy)]
#[serde(rename_all = "snake_case")]
enum Kind {
    Box,
    Sphere,
    Ellipsoid,
    Cylinder,
    HollowCylinder,
    Point,
    Mesh,
}

impl Kind {
    fn name(self) -> &'static str {
        match self {
            Kind::Box => "box",
            Kind::Sphere => "sphere",
            Kind::Ellipsoid => "ellipsoid",
            Kind::Cylinder => "cylinder",
            Kind::HollowCylinder => "hollow_cylinder",
            Kind::Point => "point",
            Kind::Mesh => "mesh",
        }
    }

    /// The keys this kind accepts besides `kind`, `name` and `offset`.
    fn accepts(self) -> &'static [&'static str] {
        match self {
            Kind::Box | Kind::Ellipsoid => &["mass", "size", "rotation_deg"],
            Kind::Sphere => &["mass", "radius", "rotation_deg"],
            Kind::Cylinder => &["mass", "radius", "length", "rotation_deg"],
            Kind::HollowCylinder => &["mass", "radius", "inner_radius", "length", "rotation_deg"],
            Kind::Point => &["mass"],
            Kind::Mesh => &["mass", "density", "path", "rotation_deg"],
        }
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawPart {
    kind: Kind,
    name: Option<String>,
    mass: Option<f64>,
    density: Option<f64>,
    size: Option<[f64; 3]>,
    radius: Option<f64>,
    inner_radius: Option<f64>,
    length: Option<f64>,
    path: Option<PathBuf>,
    #[serde(default)]
    offset: [f64; 3],
    rotation_deg: Option<[f64; 3]>,
}

impl RawPart {
    fn given(&self) -> Vec<&'static str> {
        let keys = [
            ("mass", self.mass.is_some()),
            ("density", self.density.is_some()),
            ("size", self.size.is_some()),
            ("radius", self.radius.is_some()),
            ("inner_radius", self.inner_radius.is_some()),
            ("length", self.length.is_some()),
            ("path", self.path.is_some()),
            ("rotation_deg", self.rotation_deg.is_some()),
        ];
        keys.iter().filter(|(_, g)| *g).map(|(k, _)| *k).collect()
    }

    fn need<T: Copy>(&self, field: &'static str, value: Option<T>) -> Result<T, PartError> {
        value.ok_or(PartError::Missing {
            kind: self.kind.name(),
            field,
        })
    }
}

/// One part of a body, resolved and placed in body axes.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyPart {
    /// The part's name, if it has one.
    pub name: Option<String>,
    /// The part's kind as written in the file (`"box"`, `"mesh"`, …).
    pub kind: &'static str,
    /// Its mass.
    pub mass: f64,
    /// Its centre of gravity in body axes.
    pub centre_of_gravity: Vector3<f64>,
    /// Its own mass properties, placed; `None` for a point mass.
    solid: Option<MassProperties>,
}

/// A body described by a TOML file: its parts, each already checked and placed.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyFile {
    parts: Vec<BodyPart>,
}

impl BodyFile {
    /// Reads and checks a body file; meshes are loaded relative to its folder.
    pub fn load(path: &Path) -> Result<Self, BodyFileError> {
        let text = std::fs::read_to_string(path).map_err(|error| BodyFileError::Read {
            path: path.to_path_buf(),
            error,
        })?;
        Self::parse(&text, path.parent().unwrap_or(Path::new(".")))
    }

    /// Parses and checks a body description; mesh paths are relative to `base`.
    pub fn parse(text: &str, base: &Path) -> Result<Self, BodyFileError> {
        let raw: RawFile = toml::from_str(text).map_err(BodyFileError::Syntax)?;
        if raw.part.is_empty() {
            return Err(BodyFileError::NoParts);
        }
        let parts = raw
            .part
            .into_iter()
            .enumerate()
            .map(|(i, value)| resolve(i + 1, value, base))
            .collect::<Result<_, _>>()?;
        Ok(Self { parts })
    }

    /// The parts, in the order of the file.
    pub fn parts(&self) -> &[BodyPart] {
        &self.parts
    }

    /// The mass properties of the whole body (4.23 over the parts).
    pub fn mass_properties(&self) -> Result<MassProperties, BodyFileError> {
        let mut body = Composite::new();
        for part in &self.parts {
            match &part.solid {
                Some(solid) => body.add(solid),
                None => body
                    .add_point(part.mass, part.centre_of_gravity)
                    .map_err(BodyFileError::Combination)?,
            };
        }
        body.build().map_err(BodyFileError::Combination)
    }
}

fn resolve(index: usize, value: toml::Value, base: &Path) -> Result<BodyPart, BodyFileError> {
    let label = |name: &Option<String>| {
        name.as_ref()
            .map_or(String::new(), |n| format!(" (\"{n}\")"))
    };
    let raw = RawPart::deserialize(value).map_err(|e| BodyFileError::Part {
        index,
        label: String::new(),
        error: Box::new(PartError::Field(e)),
    })?;
    part(&raw, base).map_err(|error| BodyFileError::Part {
        index,
        label: label(&raw.name),
        error: Box::new(error),
    })
}

fn part(raw: &RawPart, base: &Path) -> Result<BodyPart, PartError> {
    let kind = raw.kind;
    if let Some(field) = raw
        .given()
        .into_iter()
        .find(|f| !kind.accepts().contains(f))
    {
        return Err(PartError::NotApplicable {
            kind: kind.name(),
            field,
        });
    }
    let offset = Vector3::from(raw.offset);
    let (mass, centre, solid) = match kind {
        Kind::Point => {
            let mass = super::error::positive("mass", raw.need("mass", raw.mass)?)?;
            super::error::finite3(["offset[0]", "offset[1]", "offset[2]"], &offset)?;
            (mass, offset, None)
        }
        _ => {
            let rotation = rotation_from_degrees(raw.rotation_deg.unwrap_or_default())?;
            let solid = own_solid(raw, base)?.placed(&offset, &rotation)?;
            (solid.mass(), solid.centre_of_gravity(), Some(solid))
        }
    };
    Ok(BodyPart {
        name: raw.name.clone(),
        kind: kind.name(),
        mass,
        centre_of_gravity: centre,
        solid,
    })
}

/// The part in its own axes, before it is placed.
fn own_solid(raw: &RawPart, base: &Path) -> Result<MassProperties, PartError> {
    let mass = || raw.need("mass", raw.mass);
    Ok(match raw.kind {
        Kind::Box => solid_box(mass()?, raw.need("size", raw.size)?)?,
        Kind::Ellipsoid => ellipsoid(mass()?, raw.need("size", raw.size)?)?,
        Kind::Sphere => sphere(mass()?, raw.need("radius", raw.radius)?)?,
        Kind::Cylinder => solid_cylinder(
            mass()?,
            raw.need("radius", raw.radius)?,
            raw.need("length", raw.length)?,
        )?,
        Kind::HollowCylinder => hollow_cylinder(
            mass()?,
            raw.need("inner_radius", raw.inner_radius)?,
            raw.need("radius", raw.radius)?,
            raw.need("length", raw.length)?,
        )?,
        Kind::Mesh => mesh_solid(raw, base)?,
        Kind::Point => unreachable!("point masses have no solid; handled by the caller"),
    })
}

fn mesh_solid(raw: &RawPart, base: &Path) -> Result<MassProperties, PartError> {
    let path = base.join(raw.path.as_ref().ok_or(PartError::Missing {
        kind: "mesh",
        field: "path",
    })?);
    let mass = match (raw.mass, raw.density) {
        (Some(total), None) => MeshMass::Total(total),
        (None, Some(density)) => MeshMass::Density(density),
        _ => return Err(PartError::MassOrDensity),
    };
    let mesh_error = |error| PartError::Mesh {
        path: path.clone(),
        error,
    };
    let mesh = Mesh::load_stl(&path).map_err(mesh_error)?;
    mesh.mass_properties(mass).map_err(mesh_error)
}
