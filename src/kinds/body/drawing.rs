//! What a body's run draws, in the shapes of [`crate::output::drawing`]: its state a panel a
//! column, its attitude (a spatial body's and a top's), its track in space axes (a body that
//! moves in the plane), the drift of its energy where the energy is conserved, its polhode
//! where it turns free of moments about G, a spatial body's profile where it leaves the plane,
//! and its view. The family's layout is said here, in the columns it names; the command reads
//! them by name.
//!
//! The view draws each family as what it is:
//!
//! - a spatial body: the uniform box with its mass and principal moments (4.20–4.21 turned
//!   round), its sides along the principal axes, so a box of the same mass and moments turns
//!   as the body does; a body in water (buoyancy or damping) the solid cylinder of the same
//!   moments, on the water; ω and H = I ω drawn from G; a body whose G stays put (a free spin)
//!   trails the tip of the axis it spins most about at the start, any other its G, over a
//!   floor under its path;
//! - the heavy top: a cone from the pivot to a disc at G, z up, on the floor through the pivot;
//! - the pendulum: its rod from the pivot to G and a bob at G, swinging about the pivot's y;
//! - a planar body: a plate (sides 2 : 1) with its mass and I_zz, or for a body about midship a
//!   hull of length 4 √(I_zz/M) (a radius of gyration of L/4) and a beam of L/7, on the water.

use super::{Body, BodyScene, SceneLoads};
use crate::Short;
use crate::models::{Family, Kinematics};
use crate::output::drawing::{
    Attitude, Coordinate, Drawing, EnergyDrift, Ground, Orientation, Panels, Polhode, Profile,
    Shape, Solid, Spin, Track, Trail, View,
};

/// What the plots and the view draw of the body, in the order its files are written.
pub(super) fn drawings(scene: &BodyScene) -> Vec<Drawing> {
    let title = scene.title.clone();
    let info = scene.selection.info;
    let mut drawings = vec![Drawing::Panels(Panels {
        title: title.clone(),
        columns: scene.state_names(),
    })];
    let turns = matches!(info.family, Family::Spatial | Family::Top);
    if let Some(kinematics) = info.kinematics.filter(|_| turns) {
        drawings.push(Drawing::Attitude(Attitude {
            title: title.clone(),
            orientation: orientation(Some(kinematics)),
        }));
    }
    if !matches!(info.family, Family::Pendulum | Family::Top) {
        drawings.push(Drawing::Track(Track {
            title: title.clone(),
            what: "track in space axes".into(),
            across: (column("x"), "x [m]".into()),
            up: (column("y"), "y [m]".into()),
            marks: Vec::new(),
            outline: None,
        }));
    }
    if scene.loads.potential_energy(&scene.initial).is_some() {
        drawings.push(Drawing::EnergyDrift(EnergyDrift {
            title: title.clone(),
        }));
    }
    if let Body::Spatial { inertia, .. } = &scene.body {
        if scene.loads.is_free() || scene.loads.uniform_gravity_only().is_some() {
            drawings.push(Drawing::Polhode(Polhode {
                title: title.clone(),
                spin: spin(rows(inertia.matrix())),
            }));
        }
        drawings.push(Drawing::Profile(Profile {
            title: title.clone(),
            position: ["x", "y", "z"].map(column),
            when_level: false,
        }));
    }
    drawings.push(Drawing::View(Box::new(view(scene, title))));
    drawings
}

/// A column of the rows, by its name.
fn column(name: &str) -> String {
    name.to_owned()
}

/// A matrix as rows.
fn rows(m: nalgebra::Matrix3<f64>) -> [[f64; 3]; 3] {
    [0, 1, 2].map(|r| [m[(r, 0)], m[(r, 1)], m[(r, 2)]])
}

/// The attitude of a spatial body or a top, from its Euler angles or its quaternion as the
/// rows give it.
fn orientation(kinematics: Option<Kinematics>) -> Orientation {
    match kinematics {
        Some(Kinematics::Euler) => Orientation::EulerAngles(["phi", "theta", "psi"].map(column)),
        _ => Orientation::QuaternionAsIs(["q0", "q1", "q2", "q3"].map(column)),
    }
}

/// The body rates p, q, r and the tensor about G.
fn spin(inertia_about_g: [[f64; 3]; 3]) -> Spin {
    Spin {
        omega: ["p", "q", "r"].map(column),
        inertia_about_g,
    }
}

/// The view of the body moving, every column in its readout.
fn view(scene: &BodyScene, title: String) -> View {
    let turning = orientation(scene.selection.info.kinematics);
    let pivot = || [Coordinate::Zero, Coordinate::Zero, Coordinate::Zero];
    match &scene.body {
        Body::Spatial { mass, inertia } => {
            let solid = Solid {
                mass: *mass,
                inertia_about_g: rows(inertia.matrix()),
            };
            let water = in_water(&scene.loads);
            let (shape, ground) = match water {
                true => (Shape::Cylinder(solid), Ground::Water),
                false => (Shape::Box(solid), Ground::BelowPath),
            };
            let position = ["x", "y", "z"].map(|c| Coordinate::Column(column(c)));
            View {
                trail: Trail::TipWhereStill {
                    axis: spin_axis(&scene.initial),
                    reference: "G".into(),
                },
                ground,
                spin: Some(spin(solid.inertia_about_g)),
                notes: (water.then(|| "the blue plane is the water's surface, z = 0".into()))
                    .into_iter()
                    .collect(),
                ..View::moving(title, shape, position, turning)
            }
        }
        Body::Top {
            mass, inertia, h, ..
        } => {
            let shape = Shape::Top {
                mass: *mass,
                axial: inertia.matrix()[(2, 2)],
                h: *h,
            };
            View {
                trail: Trail::Point([0.0, 0.0, *h], "G".into()),
                z_up: true,
                camera: Some([0.0, 0.0, 0.6 * h]),
                spin: Some(spin(rows(inertia.matrix()))),
                ..View::moving(title, shape, pivot(), turning)
            }
        }
        Body::Pendulum(p) => {
            let shape = Shape::Pendulum {
                h: p.h(),
                i0: p.i0(),
                mass: p.mass(),
            };
            let swing = Orientation::Pitch(column("theta"));
            View {
                trail: Trail::Point([0.0, 0.0, p.h()], "G".into()),
                ground: Ground::Floor(1.4 * p.h()),
                camera: Some([0.0; 3]),
                ..View::moving(title, shape, pivot(), swing)
            }
        }
        Body::Planar { mass, izz, .. } => {
            let position = [
                Coordinate::Column(column("x")),
                Coordinate::Column(column("y")),
                Coordinate::Zero,
            ];
            let heading = Orientation::Heading(column("psi"));
            let plate = Shape::Plate {
                mass: *mass,
                izz: *izz,
            };
            let view = View {
                trail: Trail::Point([0.0; 3], "the body origin".into()),
                ..View::moving(title, plate, position, heading)
            };
            match scene.selection.info.family {
                Family::PlanarMidship => hull(view, *mass, *izz),
                _ => view,
            }
        }
    }
}

/// The view of a planar body about midship: a hull on the water, of length 4 √(I_zz/M) (a
/// radius of gyration of L/4 about G) and the assumed L/B.
fn hull(view: View, mass: f64, izz: f64) -> View {
    let length = 4.0 * (izz / mass).sqrt();
    let beam = length / Shape::ASSUMED_LENGTH_OVER_BEAM;
    let note = format!(
        "a hull of length {} m (a radius of gyration of L/4 about G) and beam {} m \
         (L/B = {} assumed)",
        Short(length),
        Short(beam),
        Shape::ASSUMED_LENGTH_OVER_BEAM
    );
    View {
        shape: Shape::Waterline { length, beam },
        ground: Ground::Water,
        notes: vec![note],
        ..view
    }
}

/// The body axis a spatial body spins most about at the start (p, q, r of its initial state;
/// the last of equals), which its view trails the tip of where its G stays put.
fn spin_axis(initial: &[f64]) -> usize {
    let rate = |k: usize| initial.get(k).copied().unwrap_or(0.0).abs();
    (3..6)
        .max_by(|&a, &b| rate(a).total_cmp(&rate(b)))
        .unwrap_or(3)
        - 3
}

/// Whether water acts on a spatial body: buoyancy, or any damping.
fn in_water(loads: &SceneLoads) -> bool {
    match loads {
        SceneLoads::Spatial(l) => {
            l.buoyancy != 0.0 || l.linear.iter().chain(&l.quadratic).any(|c| *c != 0.0)
        }
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_free_spin_trails_the_axis_it_spins_most_about() {
        assert_eq!(spin_axis(&[0.0, 0.0, 0.0, 0.1, -3.0, 2.0]), 1);
        assert_eq!(spin_axis(&[0.0, 0.0, 0.0, 0.0, 0.0, 40.0]), 2);
        // No rates at all: the last of equals, body z.
        assert_eq!(spin_axis(&[]), 2);
    }
}
