//! Mass properties: the mass, the centre of gravity G and the inertia tensor about G that every
//! model needs (the chapter's part 4.2), built from what a user actually has.
//!
//! - [`sphere`], [`solid_box`], [`ellipsoid`], [`solid_cylinder`], [`hollow_cylinder`]: the
//!   uniform solids whose tensors the chapter derives (4.18–4.22, exercise 4.1), and cylinders;
//! - [`Mesh`]: a solid bounded by a closed triangle mesh (an STL file from CAD);
//! - [`Composite`]: parts placed at offsets and rotations, combined by Steiner's theorem (4.23);
//! - [`MassProperties`]: the result, with radii of gyration (4.16–4.17) and principal axes;
//! - [`BodyFile`]: the TOML description read by `eom mass`;
//! - [`MassReport`]: what `eom mass --json` prints of it.
//!
//! Every tensor built here passes through [`crate::InertiaTensor::from_matrix`], so an
//! unphysical body is an error that says which condition fails.

mod composite;
mod description;
mod error;
mod gyration;
mod mesh;
mod primitives;
mod properties;
mod report;
mod steiner;

pub use composite::Composite;
pub use description::{BodyFile, BodyFileError, PartError};
pub use error::MassError;
pub use gyration::{PrincipalAxes, radii_of_gyration, radius_of_gyration};
pub use mesh::{Mesh, MeshError, MeshMass};
pub use primitives::{ellipsoid, hollow_cylinder, solid_box, solid_cylinder, sphere};
pub use properties::{MassProperties, rotation_from_degrees};
pub use report::{AboutReport, MassReport, PartReport};
pub use steiner::{steiner, steiner_shift, steiner_to_g};
