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
//!   midship a hull of length 4 √(I_zz/M) (a radius of gyration of L/4) and a beam of L/7.
//!
//! Any other run's view is drawn as its kind says it ([`View`]): a waterline of the length and
//! beam given, the solid cylinder of a body's mass and principal moments, or an aircraft of
//! the size given, moved by the columns it names. The panel of the page says which of these
//! it drew, and what it assumed.

use super::record::Kept;
use anyhow::{Context, Result};
use eom::Short;
use eom::models::state_with_unit;
use eom::models::{Family, Kinematics};
use eom::nalgebra::{Matrix3, UnitQuaternion, Vector3};
use eom::output::drawing::{BodyShape, Coordinate, Orientation, RigidBody, Shape as Drawn, View};
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
        .map(|(name, values)| (readout_label(name), values.as_slice()))
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

/// The body's initial state entry `k` (0 where it has none).
fn initial(body: &RigidBody, k: usize) -> f64 {
    body.initial.get(k).copied().unwrap_or(0.0)
}

/// A matrix as rows.
fn rows(m: &Matrix3<f64>) -> [[f64; 3]; 3] {
    [0, 1, 2].map(|r| [m[(r, 0)], m[(r, 1)], m[(r, 2)]])
}

/// The attitude quaternion of every row, from the state entries at `first` on (0 for an
/// entry the state does not have).
fn quaternions(columns: &Columns, kinematics: Option<Kinematics>, first: usize) -> [Vec<f64>; 4] {
    let zeros = vec![0.0; columns.time.len()];
    let entry = |k: usize| (columns.state.get(first + k)).map_or(zeros.as_slice(), Vec::as_slice);
    match kinematics {
        Some(Kinematics::Euler) => from_euler_angles([entry(0), entry(1), entry(2)]),
        _ => [0, 1, 2, 3].map(|k| entry(k).to_vec()),
    }
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
    let cylinder = water.then(|| cylinder(mass, moments, axes)).flatten();
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

/// The solid cylinder with a body's mass and moments, along the principal axis nearest body x;
/// `None` where no cylinder has them.
fn cylinder(mass: f64, moments: [f64; 3], axes: Matrix3<f64>) -> Option<(Shape, f64, String)> {
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
        let beam = length / Drawn::ASSUMED_LENGTH_OVER_BEAM;
        let note = format!(
            "a hull of length {} m (a radius of gyration of L/4 about G) and beam {} m \
             (L/B = {} assumed)",
            Short(length),
            Short(beam),
            Drawn::ASSUMED_LENGTH_OVER_BEAM
        );
        (Shape::Waterline { length, beam }, true, note)
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

/// Writes the `view.html` of a run whose kind says its view ([`View`]) into `out`: its shape
/// moved by the columns it names, its readout those columns (every column where it names
/// none), each labelled with its unit.
pub fn write_drawn(out: &Path, view: &View, kept: &Kept) -> Result<PathBuf> {
    let (shape, mut notes) = drawn_shape(&view.shape)?;
    notes.extend(view.notes.iter().cloned());
    let n = kept.columns.time.len();
    let coordinate = |c: &Coordinate| -> Result<Vec<f64>> {
        Ok(match c {
            Coordinate::Column(name) => kept.column(name)?.to_vec(),
            Coordinate::Negated(name) => kept.column(name)?.iter().map(|v| -v).collect(),
            Coordinate::Zero => vec![0.0; n],
        })
    };
    let [x, y, z] = &view.position;
    let attitude = match &view.orientation {
        Orientation::Heading(psi) => about_axis(kept.column(psi)?, 2),
        Orientation::Quaternion(names) => {
            let [q0, q1, q2, q3] = [0, 1, 2, 3].map(|k| kept.column(&names[k]));
            unit([q0?, q1?, q2?, q3?])
        }
        Orientation::EulerAngles(names) => {
            let [phi, theta, psi] = [0, 1, 2].map(|k| kept.column(&names[k]));
            from_euler_angles([phi?, theta?, psi?])
        }
    };
    let readout = match &view.readout {
        Some(names) => (names.iter())
            .map(|name| Ok((readout_label(name), kept.column(name)?)))
            .collect::<Result<Vec<_>>>()?,
        None => (kept.names.iter().zip(&kept.columns.state))
            .map(|(name, values)| (readout_label(name), values.as_slice()))
            .collect(),
    };
    let input = ViewInput {
        title: &view.title,
        shape,
        axes: SpaceAxes::ZDown,
        time: &kept.columns.time,
        position: [coordinate(x)?, coordinate(y)?, coordinate(z)?],
        attitude,
        readout,
        vectors: None,
        trail: ([0.0; 3], view.trail.clone()),
        camera: CameraTarget::Follow,
        floor: 0.0,
        water: view.water,
        notes,
    };
    write_view(out, &input).with_context(|| format!("writing the view into {}", out.display()))
}

/// The view's shape of a drawn one, with what the page says of how it was made.
fn drawn_shape(shape: &Drawn) -> Result<(Shape, Vec<String>)> {
    Ok(match *shape {
        Drawn::Waterline { length, beam } => (Shape::Waterline { length, beam }, Vec::new()),
        Drawn::Cylinder(solid) => {
            let inertia = Matrix3::from_fn(|r, c| solid.inertia_about_g[r][c]);
            let (moments, axes) = principal(inertia);
            match cylinder(solid.mass, moments, axes) {
                Some((shape, _, note)) => (shape, vec![note]),
                None => anyhow::bail!(
                    "no solid cylinder has the body's mass {} kg and principal moments {:?} kg m²",
                    Short(solid.mass),
                    moments
                ),
            }
        }
        Drawn::Aircraft(airframe) => (Shape::Aircraft(airframe), Vec::new()),
    })
}

/// A column's label as the readout writes it, with its unit and a space before it:
/// `alpha[rad]` and `psi` (a state whose unit is known) as `alpha [rad]` and `psi [rad]`, so
/// that an angle shows in degrees.
fn readout_label(name: &str) -> String {
    let with_unit = match name.contains('[') {
        true => name.to_owned(),
        false => state_with_unit(name),
    };
    match with_unit.split_once('[') {
        Some((base, unit)) => format!("{base} [{unit}"),
        None => with_unit,
    }
}

/// The quaternion of each row's Euler angles (roll, pitch, yaw; z–y–x).
fn from_euler_angles([phi, theta, psi]: [&[f64]; 3]) -> [Vec<f64>; 4] {
    let mut attitude: [Vec<f64>; 4] = Default::default();
    for ((phi, theta), psi) in phi.iter().zip(theta).zip(psi) {
        let q = UnitQuaternion::from_euler_angles(*phi, *theta, *psi);
        for (column, v) in attitude.iter_mut().zip([q.w, q.i, q.j, q.k]) {
            column.push(v);
        }
    }
    attitude
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
