//! The body file read by `eom mass`: a TOML list of parts (primitives, point masses, meshes),
//! each placed in body axes.
//!
//! ```toml
//! [[part]]
//! name = "hull"                  # optional, for messages
//! kind = "box"                   # box | sphere | ellipsoid | cylinder | hollow_cylinder
//!                                # | point | mesh | tensor
//! mass = 1200.0
//! size = [10.0, 2.0, 2.0]        # L, B, D
//! offset = [0.0, 0.0, -0.5]      # where the part's own origin (its G, for a primitive) goes
//! rotation_deg = [0.0, 0.0, 0.0] # roll, pitch, yaw: E = Rz(ψ) Ry(θ) Rx(φ) as in 4.57
//! ```
//!
//! A `tensor` part is a body whose properties are already known (from a swing test or a CAD
//! report): its `mass` and `inertia = [Ixx, Iyy, Izz, Ixy, Iyz, Izx]` about its own G, products
//! with the chapter's sign (4.14). It is checked like any tensor: symmetric, positive definite,
//! triangle inequalities, and an error says which condition fails.
//!
//! Parts are numbered from 1 in the order they appear; an unknown key, a missing key and a key
//! that does not belong to the part's kind are errors naming the part and the key. A mesh's
//! `path` is relative to the body file's folder.

use super::composite::Composite;
use super::error::MassError;
use super::mesh::{Mesh, MeshError, MeshMass};
use super::primitives::{ellipsoid, hollow_cylinder, solid_box, solid_cylinder, sphere};
use super::properties::{MassProperties, rotation_from_degrees};
use crate::InertiaTensor;
use crate::validate::positive;
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
    Tensor,
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
            Kind::Tensor => "tensor",
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
            Kind::Tensor => &["mass", "inertia", "rotation_deg"],
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
    inertia: Option<[f64; 6]>,
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
            ("inertia", self.inertia.is_some()),
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
            let mass = positive("mass", raw.need("mass", raw.mass)?).map_err(MassError::from)?;
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
        Kind::Tensor => {
            let [ixx, iyy, izz, ixy, iyz, izx] = raw.need("inertia", raw.inertia)?;
            let inertia =
                InertiaTensor::new(ixx, iyy, izz, ixy, iyz, izx).map_err(MassError::from)?;
            MassProperties::new(mass()?, Vector3::zeros(), inertia)?
        }
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

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Rotation3;

    fn parse(text: &str) -> Result<BodyFile, BodyFileError> {
        BodyFile::parse(text, Path::new("."))
    }

    fn part_error(text: &str) -> (usize, String) {
        match parse(text).unwrap_err() {
            BodyFileError::Part { index, error, .. } => (index, error.to_string()),
            other => panic!("expected a part error, got {other}"),
        }
    }

    #[test]
    fn every_primitive_kind_combines_as_built_by_hand() {
        let text = r#"
            [[part]]
            kind = "box"
            mass = 10.0
            size = [4, 2, 1]
            offset = [1.0, 0.0, 0.5]
            rotation_deg = [0.0, 0.0, 30.0]
            [[part]]
            kind = "sphere"
            mass = 2
            radius = 0.5
            offset = [-2.0, 0.5, 0.0]
            [[part]]
            kind = "ellipsoid"
            mass = 3
            size = [2, 1, 1]
            [[part]]
            kind = "cylinder"
            mass = 1.5
            radius = 0.2
            length = 3
            rotation_deg = [10, 20, 0]
            [[part]]
            kind = "hollow_cylinder"
            mass = 1
            inner_radius = 0.1
            radius = 0.3
            length = 1
            offset = [0, 0, -1]
            [[part]]
            kind = "point"
            mass = 0.5
            offset = [0, 2, 0]
            [[part]]
            kind = "tensor"
            mass = 4
            inertia = [3, 4, 5, -0.5, 0.25, 0.1]
            offset = [0.5, 0.5, 0.5]
            rotation_deg = [0, 90, 0]
        "#;
        let from_file = parse(text).unwrap().mass_properties().unwrap();
        let turn = |deg: [f64; 3]| rotation_from_degrees(deg).unwrap();
        let mut body = Composite::new();
        let placed = |p: MassProperties, at: [f64; 3], r: Rotation3<f64>| {
            p.placed(&Vector3::from(at), &r).unwrap()
        };
        let none = Rotation3::identity();
        body.add(&placed(
            solid_box(10.0, [4.0, 2.0, 1.0]).unwrap(),
            [1.0, 0.0, 0.5],
            turn([0.0, 0.0, 30.0]),
        ));
        body.add(&placed(sphere(2.0, 0.5).unwrap(), [-2.0, 0.5, 0.0], none));
        body.add(&placed(
            ellipsoid(3.0, [2.0, 1.0, 1.0]).unwrap(),
            [0.0; 3],
            none,
        ));
        body.add(&placed(
            solid_cylinder(1.5, 0.2, 3.0).unwrap(),
            [0.0; 3],
            turn([10.0, 20.0, 0.0]),
        ));
        body.add(&placed(
            hollow_cylinder(1.0, 0.1, 0.3, 1.0).unwrap(),
            [0.0, 0.0, -1.0],
            none,
        ));
        body.add_point(0.5, Vector3::new(0.0, 2.0, 0.0)).unwrap();
        let given = InertiaTensor::new(3.0, 4.0, 5.0, -0.5, 0.25, 0.1).unwrap();
        let given = MassProperties::new(4.0, Vector3::zeros(), given).unwrap();
        body.add(&placed(given, [0.5; 3], turn([0.0, 90.0, 0.0])));
        // The same operations in the same order: equal to the last bit.
        assert_eq!(from_file, body.build().unwrap());
    }

    #[test]
    fn unknown_key_names_part_and_key() {
        let (index, message) = part_error(
            "[[part]]\nkind = \"box\"\nmass = 1\nsize = [1, 1, 1]\n[[part]]\nkind = \"box\"\nmass = 1\nsise = [1, 1, 1]",
        );
        assert_eq!(index, 2);
        assert!(message.contains("unknown field `sise`"), "{message}");
    }

    #[test]
    fn missing_and_misplaced_keys_are_named() {
        let (_, message) = part_error("[[part]]\nkind = \"sphere\"\nmass = 1");
        assert_eq!(message, "a sphere needs `radius`");
        let (_, message) =
            part_error("[[part]]\nkind = \"sphere\"\nmass = 1\nradius = 1\nlength = 2");
        assert_eq!(message, "`length` does not apply to a sphere");
        let (_, message) =
            part_error("[[part]]\nkind = \"point\"\nmass = 1\nrotation_deg = [0, 0, 1]");
        assert_eq!(message, "`rotation_deg` does not apply to a point");
        let (_, message) = part_error("[[part]]\nmass = 1");
        assert!(message.contains("missing field `kind`"), "{message}");
        let (_, message) =
            part_error("[[part]]\nkind = \"box\"\nmass = \"heavy\"\nsize = [1, 1, 1]");
        assert!(
            message.contains("in `mass`") && !message.contains('\n'),
            "{message}"
        );
    }

    #[test]
    fn an_impossible_given_tensor_says_which_condition_fails() {
        let text = "[[part]]\nname = \"payload\"\nkind = \"tensor\"\nmass = 1\ninertia = [1, 1, 3, 0, 0, 0]";
        let message = parse(text).unwrap_err().to_string();
        assert_eq!(
            message,
            "part 1 (\"payload\"): triangle inequality fails: Ixx + Iyy = 2 < Izz = 3"
        );
    }

    #[test]
    fn a_mesh_needs_exactly_one_of_mass_and_density() {
        let both = "[[part]]\nkind = \"mesh\"\npath = \"a.stl\"\nmass = 1\ndensity = 2";
        assert_eq!(
            part_error(both).1,
            "a mesh needs exactly one of `mass` and `density`"
        );
        let neither = "[[part]]\nkind = \"mesh\"\npath = \"a.stl\"";
        assert_eq!(
            part_error(neither).1,
            "a mesh needs exactly one of `mass` and `density`"
        );
    }

    #[test]
    fn bad_values_name_the_part_by_its_name() {
        let err = parse("[[part]]\nname = \"keel\"\nkind = \"box\"\nmass = -4\nsize = [1, 1, 1]")
            .unwrap_err();
        assert_eq!(
            err.to_string(),
            "part 1 (\"keel\"): mass must be positive and finite, got -4"
        );
    }

    #[test]
    fn file_level_faults_are_reported() {
        assert!(matches!(parse(""), Err(BodyFileError::NoParts)));
        assert!(matches!(parse("parts = 1"), Err(BodyFileError::Syntax(_))));
        assert!(matches!(parse("[[part]"), Err(BodyFileError::Syntax(_))));
        let line = "[[part]]\nkind = \"point\"\nmass = 1\n[[part]]\nkind = \"point\"\nmass = 1\noffset = [1, 0, 0]";
        let err = parse(line).unwrap().mass_properties().unwrap_err();
        assert!(matches!(err, BodyFileError::Combination(_)), "{err}");
        let missing = BodyFile::load(Path::new("/nonexistent/body.toml")).unwrap_err();
        assert!(matches!(missing, BodyFileError::Read { .. }));
    }
}
