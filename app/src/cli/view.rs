//! The 3-D view of a run: the body's shape made from the scene, and the columns kept,
//! handed to [`eom_cli::view`].
//!
//! How each family is drawn, and from what:
//!
//! - a spatial body: the uniform box with its mass and principal moments (4.20–4.21 turned
//!   round), its sides along the principal axes (the inertia tensor's eigenvectors), so a box
//!   of the same mass and moments turns as the body does; a body in water (buoyancy or
//!   damping) a solid cylinder from the same moments, along the principal axis nearest
//!   body x; ω and H = I ω drawn from G;
//! - the heavy top: a cone from the pivot to a disc at G, its radius from I₃ = M R²/2;
//! - the pendulum: its rod from the pivot to G and a bob at G;
//! - a planar body: a plate (sides 2 : 1) with its mass and I_zz, or for a body about
//!   midship a hull of length 4 √(I_zz/M) (a radius of gyration of L/4); a ship scene's
//!   hull has its L, and a beam of L/7, assumed (a ship scene has no key for it).
//!
//! The panel of the page says which of these it drew, and what it assumed.

use super::record::Kept;
use anyhow::{Context, Result};
use eom::Short;
use eom::models::state_with_unit;
use eom::models::{Family, Kinematics, state_unit};
use eom::nalgebra::{Matrix3, UnitQuaternion, Vector3};
use eom::output::drawing::{BodyShape, Flight, Hull, PlaneManoeuvre, RigidBody, SpaceManoeuvre};
use eom::output::trajectory::Columns;
use eom_cli::view::{
    CameraTarget, Shape, SpaceAxes, Vectors, ViewInput, box_sides, cylinder_size, write_view,
};
use std::path::{Path, PathBuf};

/// Writes `view.html` of a rigid body's run into `out`.
pub fn write(body: &RigidBody, kept: &Kept, out: &Path) -> Result<PathBuf> {
    let columns = &kept.columns;
    let readout: Vec<(String, &[f64])> = (kept.names.iter())
        .zip(&columns.state)
        .map(|(name, values)| (labelled(name), values.as_slice()))
        .collect();
    let matrix = |rows: [[f64; 3]; 3]| Matrix3::from_fn(|r, c| rows[r][c]);
    let mut input = match body.shape {
        BodyShape::Spatial {
            mass,
            inertia,
            in_water,
            ..
        } => spatial(body, columns, mass, matrix(inertia), in_water),
        BodyShape::Top { mass, inertia, h } => top(body, columns, mass, matrix(inertia), h),
        BodyShape::Pendulum { h, i0, mass } => pendulum(body, columns, h, i0, mass),
        BodyShape::Planar { mass, izz } => planar(body, columns, mass, izz),
    };
    input.readout = readout;
    write_view(out, &input).with_context(|| format!("writing the view into {}", out.display()))
}

/// A state name with its unit, as the panel shows it: `q [rad/s]`.
fn labelled(name: &str) -> String {
    match state_unit(name) {
        Some(unit) => format!("{name} [{unit}]"),
        None => name.to_string(),
    }
}

/// The body's initial state entry `k` (0 where it has none).
fn initial(body: &RigidBody, k: usize) -> f64 {
    body.initial.get(k).copied().unwrap_or(0.0)
}

/// A matrix as rows.
fn rows(m: &Matrix3<f64>) -> [[f64; 3]; 3] {
    [0, 1, 2].map(|r| [m[(r, 0)], m[(r, 1)], m[(r, 2)]])
}

/// The attitude quaternion of every row, from the state entries at `first` on.
fn quaternions(columns: &Columns, kinematics: Option<Kinematics>, first: usize) -> [Vec<f64>; 4] {
    let n = columns.time.len();
    let mut q: [Vec<f64>; 4] = Default::default();
    for row in 0..n {
        let entry = |k: usize| columns.state.get(first + k).map_or(0.0, |c| c[row]);
        let [w, x, y, z] = match kinematics {
            Some(Kinematics::Euler) => {
                let u = UnitQuaternion::from_euler_angles(entry(0), entry(1), entry(2));
                [u.w, u.i, u.j, u.k]
            }
            _ => [entry(0), entry(1), entry(2), entry(3)],
        };
        for (column, value) in q.iter_mut().zip([w, x, y, z]) {
            column.push(value);
        }
    }
    q
}

/// A quaternion column set of a turn about one body axis by the angles given.
fn about_axis(angles: &[f64], axis: usize) -> [Vec<f64>; 4] {
    let mut q: [Vec<f64>; 4] = Default::default();
    for &angle in angles {
        let (s, c) = (angle / 2.0).sin_cos();
        let mut value = [c, 0.0, 0.0, 0.0];
        value[1 + axis] = s;
        for (column, v) in q.iter_mut().zip(value) {
            column.push(v);
        }
    }
    q
}

/// The largest extent of a path, m.
fn extent(columns: &[&[f64]]) -> f64 {
    columns
        .iter()
        .map(|c| {
            let (lo, hi) = c
                .iter()
                .filter(|v| v.is_finite())
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                    (lo.min(*v), hi.max(*v))
                });
            if hi >= lo { hi - lo } else { 0.0 }
        })
        .fold(0.0, f64::max)
}

/// The principal moments of the tensor `inertia` and its principal axes as columns,
/// right-handed, so that a body drawn in them is not a mirror image (ones and body axes for a
/// tensor that is not physical).
fn principal(inertia: Matrix3<f64>) -> ([f64; 3], Matrix3<f64>) {
    let tensor = eom::InertiaTensor::from_matrix(inertia).ok();
    let (moments, axes) = tensor.map_or((Vector3::new(1.0, 1.0, 1.0), Matrix3::identity()), |t| {
        t.principal()
    });
    let mut axes = axes;
    if axes.determinant() < 0.0 {
        let third = -axes.column(2);
        axes.set_column(2, &third);
    }
    ([moments[0], moments[1], moments[2]], axes)
}

/// A spatial body: a box (or in water a cylinder) in its principal axes.
fn spatial<'a>(
    body: &'a RigidBody,
    columns: &'a Columns,
    mass: f64,
    inertia: Matrix3<f64>,
    water: bool,
) -> ViewInput<'a> {
    let (moments, axes) = principal(inertia);
    let mut notes = Vec::new();
    let cylinder = water.then(|| vehicle(mass, moments, axes)).flatten();
    let (shape, size) = match cylinder {
        Some((shape, size, note)) => {
            notes.push(note);
            (shape, size)
        }
        None => {
            let sides = box_sides(mass, moments);
            notes.push(format!(
                "the uniform box of mass {} kg with the principal moments {} kg m² \
                 (sides {} × {} × {} m), along the principal axes",
                Short(mass),
                moments.map(|m| Short(m).to_string()).join(", "),
                Short(sides[0]),
                Short(sides[1]),
                Short(sides[2])
            ));
            let size = sides.iter().fold(0.0f64, |m, s| m.max(*s));
            (
                Shape::Box {
                    sides,
                    axes: rows(&axes),
                },
                size,
            )
        }
    };
    let position = [6, 7, 8].map(|k| columns.state[k].clone());
    let path = extent(&[&position[0], &position[1], &position[2]]);
    // A body whose G stays put (a free spin) trails the tip of the axis it spins most about.
    let trail = if path < 0.5 * size {
        let spin = (3..6)
            .max_by(|&a, &b| initial(body, a).abs().total_cmp(&initial(body, b).abs()))
            .unwrap_or(3)
            - 3;
        let mut tip = [0.0; 3];
        tip[spin] = 0.75 * size;
        (tip, format!("tip of body {}", ["x", "y", "z"][spin]))
    } else {
        ([0.0; 3], "G".to_string())
    };
    let deepest = position[2]
        .iter()
        .filter(|z| z.is_finite())
        .fold(f64::NEG_INFINITY, |m, z| m.max(*z));
    let floor = if water { 0.0 } else { deepest + 0.8 * size };
    if water {
        notes.push("the blue plane is the water's surface, z = 0".into());
    }
    ViewInput {
        title: &body.title,
        shape,
        axes: SpaceAxes::ZDown,
        time: &columns.time,
        position,
        attitude: quaternions(columns, body.kinematics, 9),
        readout: Vec::new(),
        vectors: Some(Vectors {
            omega: [3, 4, 5],
            inertia: rows(&inertia),
        }),
        trail,
        camera: CameraTarget::Follow,
        floor,
        water,
        notes,
    }
}

/// A vehicle: the solid cylinder with the body's mass and moments, along the principal axis
/// nearest body x; `None` where no cylinder has them.
fn vehicle(mass: f64, moments: [f64; 3], axes: Matrix3<f64>) -> Option<(Shape, f64, String)> {
    let along = (0..3).max_by(|&a, &b| axes[(0, a)].abs().total_cmp(&axes[(0, b)].abs()))?;
    let others: Vec<usize> = (0..3).filter(|&k| k != along).collect();
    let transverse = (moments[others[0]] + moments[others[1]]) / 2.0;
    let (length, diameter) = cylinder_size(mass, moments[along], transverse)?;
    // The cylinder's axis first, pointing forward (+x).
    let sign = axes[(0, along)].signum();
    let first = axes.column(along) * sign;
    let second = axes.column(others[0]).into_owned();
    let third = first.cross(&second);
    let frame = Matrix3::from_columns(&[first, second, third]);
    let note = format!(
        "the solid cylinder of mass {} kg with the moments {} kg m² about its axis and {} kg m² \
         across it: length {} m, diameter {} m",
        Short(mass),
        Short(moments[along]),
        Short(transverse),
        Short(length),
        Short(diameter)
    );
    let size = length.max(diameter);
    Some((
        Shape::Cylinder {
            length,
            diameter,
            axes: rows(&frame),
        },
        size,
        note,
    ))
}

/// The heavy top: a cone from the pivot to a disc at G, Z up.
fn top<'a>(
    body: &'a RigidBody,
    columns: &'a Columns,
    mass: f64,
    inertia: Matrix3<f64>,
    h: f64,
) -> ViewInput<'a> {
    let n = columns.time.len();
    let axial = inertia[(2, 2)];
    let radius = (2.0 * axial / mass).sqrt().clamp(0.2 * h, 1.5 * h);
    let notes = vec![format!(
        "a cone from the pivot to a disc at G, h = {} m above it along the body z-axis; \
         the disc's radius {} m from I₃ = M R²/2",
        Short(h),
        Short(radius)
    )];
    ViewInput {
        title: &body.title,
        shape: Shape::Top { h, radius },
        axes: SpaceAxes::ZUp,
        time: &columns.time,
        position: [vec![0.0; n], vec![0.0; n], vec![0.0; n]],
        attitude: quaternions(columns, body.kinematics, 3),
        readout: Vec::new(),
        vectors: Some(Vectors {
            omega: [0, 1, 2],
            inertia: rows(&inertia),
        }),
        trail: ([0.0, 0.0, h], "G".into()),
        camera: CameraTarget::Fixed([0.0, 0.0, 0.6 * h]),
        floor: 0.0,
        water: false,
        notes,
    }
}

/// The pendulum: a rod from the pivot down to G, swinging in the x–z plane.
fn pendulum<'a>(
    body: &'a RigidBody,
    columns: &'a Columns,
    h: f64,
    i0: f64,
    mass: f64,
) -> ViewInput<'a> {
    let n = columns.time.len();
    // A sphere of radius r about G has I_G = (2/5) M r²; drawn no larger than h/3.
    let i_g = (i0 - mass * h * h).max(0.0);
    let bob = (2.5 * i_g / mass).sqrt().min(h / 3.0).max(0.05 * h);
    let notes = vec![format!(
        "the rod from the pivot to G, h = {} m; θ turns it about the pivot's y-axis; the bob \
         at G is drawn {} m in radius",
        Short(h),
        Short(bob)
    )];
    ViewInput {
        title: &body.title,
        shape: Shape::Pendulum { length: h, bob },
        axes: SpaceAxes::ZDown,
        time: &columns.time,
        position: [vec![0.0; n], vec![0.0; n], vec![0.0; n]],
        attitude: about_axis(&columns.state[0], 1),
        readout: Vec::new(),
        vectors: None,
        trail: ([0.0, 0.0, h], "G".into()),
        camera: CameraTarget::Fixed([0.0; 3]),
        floor: 1.4 * h,
        water: false,
        notes,
    }
}

/// A planar body: a hull about midship, else a plate.
fn planar<'a>(body: &'a RigidBody, columns: &'a Columns, mass: f64, izz: f64) -> ViewInput<'a> {
    let family = body.family;
    let (x, y, psi) = match family {
        Family::PlanarSpaceFixed => (0, 1, 2),
        _ => (3, 4, 5),
    };
    let n = columns.time.len();
    let (shape, water, note) = if family == Family::PlanarMidship {
        let length = 4.0 * (izz / mass).sqrt();
        let beam = length / Hull::ASSUMED_LENGTH_OVER_BEAM;
        let note = format!(
            "a hull of length {} m (a radius of gyration of L/4 about G) and beam {} m \
             (L/B = {} assumed)",
            Short(length),
            Short(beam),
            Hull::ASSUMED_LENGTH_OVER_BEAM
        );
        (Shape::Hull { length, beam }, true, note)
    } else {
        // a² + b² = 12 I_zz/M with a = 2b.
        let b = (12.0 * izz / (5.0 * mass)).sqrt();
        let note = format!(
            "a plate of {} × {} m (sides 2 : 1 assumed) with the mass and I_zz",
            Short(2.0 * b),
            Short(b)
        );
        let shape = Shape::Box {
            sides: [2.0 * b, b, 0.1 * b],
            axes: rows(&Matrix3::identity()),
        };
        (shape, false, note)
    };
    ViewInput {
        title: &body.title,
        shape,
        axes: SpaceAxes::ZDown,
        time: &columns.time,
        position: [
            columns.state[x].clone(),
            columns.state[y].clone(),
            vec![0.0; n],
        ],
        attitude: about_axis(&columns.state[psi], 2),
        readout: Vec::new(),
        vectors: None,
        trail: ([0.0; 3], "the body origin".into()),
        camera: CameraTarget::Follow,
        floor: 0.0,
        water,
        notes: vec![note],
    }
}

/// Writes the `view.html` of a manoeuvre in the plane into its folder: the hull moving on
/// the water, turned by ψ, its readout the drawing's columns.
pub fn write_plane(out: &Path, drawing: &PlaneManoeuvre, kept: &Kept) -> Result<PathBuf> {
    let n = kept.columns.time.len();
    let hull = drawing.hull;
    let note = match hull.beam_assumed {
        true => format!(
            "the hull of length L = {} m, and of beam B = L/{} = {} m, assumed: a ship scene \
             has no key for the beam (its table does not need one)",
            Short(hull.length),
            Hull::ASSUMED_LENGTH_OVER_BEAM,
            Short(hull.beam)
        ),
        false => format!(
            "the hull of length L = {} m and beam B = {} m",
            Short(hull.length),
            Short(hull.beam)
        ),
    };
    let readout = (drawing.readout.iter())
        .map(|name| Ok((state_with_unit(name), kept.column(name)?)))
        .collect::<Result<Vec<_>>>()?;
    let input = ViewInput {
        title: &drawing.title,
        shape: Shape::Hull {
            length: hull.length,
            beam: hull.beam,
        },
        axes: SpaceAxes::ZDown,
        time: &kept.columns.time,
        position: [
            kept.column("x")?.to_vec(),
            kept.column("y")?.to_vec(),
            vec![0.0; n],
        ],
        attitude: about_axis(kept.column("psi")?, 2),
        readout,
        vectors: None,
        trail: ([0.0; 3], "midship".into()),
        camera: CameraTarget::Follow,
        floor: 0.0,
        water: true,
        notes: vec![note],
    };
    write_view(out, &input).with_context(|| format!("writing the view into {}", out.display()))
}

/// Writes the `view.html` of a manoeuvre in space into its folder: the solid cylinder of the
/// body's mass and principal moments about G (along the principal axis nearest body x), drawn
/// about the rows' reference point (G's offset from it, 2 cm for REMUS's origin, is not
/// drawn), moving through the water in north, east, down and turned by the run's quaternion;
/// every column in its readout.
pub fn write_space(out: &Path, drawing: &SpaceManoeuvre, kept: &Kept) -> Result<PathBuf> {
    let solid = drawing.solid;
    let inertia = Matrix3::from_fn(|r, c| solid.inertia_about_g[r][c]);
    let (moments, axes) = principal(inertia);
    let (shape, note) = match vehicle(solid.mass, moments, axes) {
        Some((shape, _, note)) => (shape, note),
        None => anyhow::bail!(
            "no solid cylinder has the body's mass {} kg and principal moments {:?} kg m²",
            Short(solid.mass),
            moments
        ),
    };
    let readout = (kept.names.iter().zip(&kept.columns.state))
        .map(|(name, values)| (labelled(name), values.as_slice()))
        .collect();
    let quaternion = [
        kept.column("q0")?,
        kept.column("q1")?,
        kept.column("q2")?,
        kept.column("q3")?,
    ];
    let input = ViewInput {
        title: &drawing.title,
        shape,
        axes: SpaceAxes::ZDown,
        time: &kept.columns.time,
        position: [
            kept.column("x")?.to_vec(),
            kept.column("y")?.to_vec(),
            kept.column("z")?.to_vec(),
        ],
        attitude: unit(quaternion),
        readout,
        vectors: None,
        trail: ([0.0; 3], "the table's origin O".into()),
        camera: CameraTarget::Follow,
        floor: 0.0,
        water: true,
        notes: vec![note],
    };
    write_view(out, &input).with_context(|| format!("writing the view into {}", out.display()))
}

/// The fuselage's length over its diameter, as the view draws an aircraft.
const FUSELAGE_FINENESS: f64 = 10.0;

/// The view of a flight (`view.html`): the aircraft from the scene's geometry (a fuselage of
/// its length along body x, wings of its span and chord, a tailplane and a fin), over the
/// ground (z = 0 at altitude 0, Z down), the attitude from the rows' Euler angles.
pub fn write_flight(out: &Path, drawing: &Flight, kept: &Kept) -> Result<PathBuf> {
    // The fuselage a tenth as thick as it is long, a transport's and a fighter's fineness
    // ratio to within a factor of two; without the scene's length, as long as the span.
    let (length, said) = match drawing.length {
        Some(length) => (length, "`geometry.length`"),
        None => (
            drawing.span,
            "the span, the scene giving no `geometry.length`",
        ),
    };
    let diameter = length / FUSELAGE_FINENESS;
    let unit = drawing.length_unit;
    let column = |name: &str, unit: &str| kept.column(&format!("{name}[{unit}]"));
    let angles = [
        column("phi", "rad")?,
        column("theta", "rad")?,
        column("psi", "rad")?,
    ];
    let mut attitude: [Vec<f64>; 4] = Default::default();
    for ((phi, theta), psi) in angles[0].iter().zip(angles[1]).zip(angles[2]) {
        let q = UnitQuaternion::from_euler_angles(*phi, *theta, *psi);
        for (column, v) in attitude.iter_mut().zip([q.w, q.i, q.j, q.k]) {
            column.push(v);
        }
    }
    let readout = (kept.names.iter().zip(&kept.columns.state))
        .map(|(name, values)| (spaced(name), values.as_slice()))
        .collect();
    let note = format!(
        "drawn from the scene's geometry: the fuselage {} {unit} long ({said}) and a tenth of \
         that across, the wings of span {} {unit} and chord {} {unit}, the tailplane a third \
         of the span",
        Short(length),
        Short(drawing.span),
        Short(drawing.chord),
    );
    let input = ViewInput {
        title: &drawing.title,
        shape: Shape::Aircraft {
            length,
            diameter,
            span: drawing.span,
            chord: drawing.chord,
            unit,
        },
        axes: SpaceAxes::ZDown,
        time: &kept.columns.time,
        position: [
            column("north", unit)?.to_vec(),
            column("east", unit)?.to_vec(),
            column("altitude", unit)?.iter().map(|h| -h).collect(),
        ],
        attitude,
        readout,
        vectors: None,
        trail: ([0.0; 3], "G".into()),
        camera: CameraTarget::Follow,
        floor: 0.0,
        water: false,
        notes: vec![note],
    };
    write_view(out, &input).with_context(|| format!("writing the view into {}", out.display()))
}

/// A column's label as the readout writes it: `alpha[rad]` as `alpha [rad]`, so that an angle
/// shows in degrees.
fn spaced(name: &str) -> String {
    match name.split_once('[') {
        Some((base, unit)) => format!("{base} [{unit}"),
        None => name.to_owned(),
    }
}

/// Quaternion columns divided by their length, row by row (a run's quaternion drifts from
/// unit length by its integrator's error).
fn unit(columns: [&[f64]; 4]) -> [Vec<f64>; 4] {
    let mut q: [Vec<f64>; 4] = Default::default();
    for row in 0..columns[0].len() {
        let value = columns.map(|c| c[row]);
        let norm = value.iter().map(|x| x * x).sum::<f64>().sqrt();
        for (column, v) in q.iter_mut().zip(value) {
            column.push(v / norm);
        }
    }
    q
}

#[cfg(test)]
mod tests {
    use super::*;
    use eom::nalgebra::Rotation3;

    #[test]
    fn euler_angles_and_the_quaternion_give_one_rotation() {
        let columns = Columns {
            time: vec![0.0],
            state: [0.3, -0.4, 1.1].iter().map(|v| vec![*v]).collect(),
            energy: vec![],
            kinetic: vec![],
        };
        let q = quaternions(&columns, Some(Kinematics::Euler), 0);
        let from_q = UnitQuaternion::from_quaternion(eom::nalgebra::Quaternion::new(
            q[0][0], q[1][0], q[2][0], q[3][0],
        ))
        .to_rotation_matrix();
        let from_euler = Rotation3::from_euler_angles(0.3, -0.4, 1.1);
        assert!((from_q.matrix() - from_euler.matrix()).abs().max() < 1e-12);
    }
}
