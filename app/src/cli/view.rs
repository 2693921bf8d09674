//! The 3-D view of a run: the shape its kind says ([`View`]) made into what the page draws,
//! moved by the columns it names, handed to [`eom_cli::view`].
//!
//! How each shape is made, and from what:
//!
//! - a hull's waterline, of the length and beam given; an aircraft, of the size given;
//! - the uniform box with a body's mass and principal moments (4.20–4.21 turned round), its
//!   sides along the principal axes (the inertia tensor's eigenvectors), so a box of the same
//!   mass and moments turns as the body does;
//! - the solid cylinder from the same moments, along the principal axis nearest body x (the
//!   box where no cylinder has them);
//! - a top: a cone from the pivot to a disc at G, its radius from I₃ = M R²/2;
//! - a pendulum: its rod from the pivot to G and a bob at G;
//! - a plate (sides 2 : 1) with a body's mass and I_zz.
//!
//! The panel of the page says which of these it drew, and what it assumed. Where the kind
//! says a spin, ω and H = I ω are drawn from G; where its trail is the tip of an axis while
//! the body stays put, or its floor under the path, the shape's size sets how far.

use super::record::Kept;
use anyhow::{Context, Result};
use eom::Short;
use eom::models::state_with_unit;
use eom::nalgebra::{Matrix3, UnitQuaternion, Vector3};
use eom::output::drawing::{
    Coordinate, Ground, Orientation, Shape as Drawn, Solid, Spin, Trail, View,
};
use eom_cli::view::{
    CameraTarget, Shape, SpaceAxes, Vectors, ViewInput, box_sides, cylinder_size, write_view,
};
use std::path::{Path, PathBuf};

/// Writes the `view.html` of a run into `out`: the shape its kind says, moved by the columns
/// it names, its readout those columns (every column where it names none), each labelled with
/// its unit.
pub fn write(out: &Path, view: &View, kept: &Kept) -> Result<PathBuf> {
    let made = made(&view.shape);
    let mut notes = made.notes;
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
    let position = [coordinate(x)?, coordinate(y)?, coordinate(z)?];
    let shown: Vec<&str> = match &view.readout {
        Some(names) => names.iter().map(String::as_str).collect(),
        None => kept.names.iter().map(String::as_str).collect(),
    };
    let readout = (shown.iter())
        .map(|name| Ok((readout_label(name), kept.column(name)?)))
        .collect::<Result<Vec<_>>>()?;
    let vectors = match &view.spin {
        Some(spin) => Some(vectors(spin, &shown)?),
        None => None,
    };
    let trail = match &view.trail {
        Trail::Point(at, name) => (*at, name.clone()),
        Trail::TipWhereStill { axis, reference } => {
            tip_where_still(&position, made.size, *axis, reference)
        }
    };
    let (floor, water) = match view.ground {
        Ground::Water => (0.0, true),
        Ground::Floor(z) => (z, false),
        Ground::BelowPath => (deepest(&position[2]) + 0.8 * made.size, false),
    };
    let input = ViewInput {
        title: &view.title,
        shape: made.shape,
        axes: match view.z_up {
            true => SpaceAxes::ZUp,
            false => SpaceAxes::ZDown,
        },
        time: &kept.columns.time,
        position,
        attitude: attitude(&view.orientation, kept)?,
        readout,
        vectors,
        trail,
        camera: match view.camera {
            Some(point) => CameraTarget::Fixed(point),
            None => CameraTarget::Follow,
        },
        floor,
        water,
        notes,
    };
    write_view(out, &input).with_context(|| format!("writing the view into {}", out.display()))
}

/// A shape as the page draws it: its size (its largest extent, in the rows' length unit) and
/// what the page says of how it was made.
struct Made {
    shape: Shape,
    size: f64,
    notes: Vec<String>,
}

/// The page's shape of a drawn one.
fn made(shape: &Drawn) -> Made {
    let plain = |shape, size| Made {
        shape,
        size,
        notes: Vec::new(),
    };
    match *shape {
        Drawn::Waterline { length, beam } => plain(Shape::Waterline { length, beam }, length),
        Drawn::Aircraft(airframe) => {
            let size = airframe.length.max(airframe.span);
            plain(Shape::Aircraft(airframe), size)
        }
        Drawn::Cylinder(solid) => {
            let (moments, axes) = principal(matrix(solid.inertia_about_g));
            cylinder(solid.mass, moments, axes).unwrap_or_else(|| uniform_box(solid))
        }
        Drawn::Box(solid) => uniform_box(solid),
        Drawn::Top { mass, axial, h } => top(mass, axial, h),
        Drawn::Pendulum { h, i0, mass } => pendulum(h, i0, mass),
        Drawn::Plate { mass, izz } => plate(mass, izz),
    }
}

/// A tensor's rows as a matrix.
fn matrix(rows: [[f64; 3]; 3]) -> Matrix3<f64> {
    Matrix3::from_fn(|r, c| rows[r][c])
}

/// The uniform box with a body's mass and principal moments, along its principal axes.
fn uniform_box(solid: Solid) -> Made {
    let (moments, axes) = principal(matrix(solid.inertia_about_g));
    let sides = box_sides(solid.mass, moments);
    let note = format!(
        "the uniform box of mass {} kg with the principal moments {} kg m² \
         (sides {} × {} × {} m), along the principal axes",
        Short(solid.mass),
        moments.map(|m| Short(m).to_string()).join(", "),
        Short(sides[0]),
        Short(sides[1]),
        Short(sides[2])
    );
    Made {
        shape: Shape::Box {
            sides,
            axes: rows(&axes),
        },
        size: sides.iter().fold(0.0f64, |m, s| m.max(*s)),
        notes: vec![note],
    }
}

/// A top: a cone from the pivot to a disc at G, the disc's radius from I₃ = M R²/2.
fn top(mass: f64, axial: f64, h: f64) -> Made {
    let radius = (2.0 * axial / mass).sqrt().clamp(0.2 * h, 1.5 * h);
    let note = format!(
        "a cone from the pivot to a disc at G, h = {} m above it along the body z-axis; \
         the disc's radius {} m from I₃ = M R²/2",
        Short(h),
        Short(radius)
    );
    Made {
        shape: Shape::Top { h, radius },
        size: h.max(2.0 * radius),
        notes: vec![note],
    }
}

/// A pendulum: a rod from the pivot down to G, a bob at G.
fn pendulum(h: f64, i0: f64, mass: f64) -> Made {
    // A sphere of radius r about G has I_G = (2/5) M r²; drawn no larger than h/3.
    let i_g = (i0 - mass * h * h).max(0.0);
    let bob = (2.5 * i_g / mass).sqrt().min(h / 3.0).max(0.05 * h);
    let note = format!(
        "the rod from the pivot to G, h = {} m; θ turns it about the pivot's y-axis; the bob \
         at G is drawn {} m in radius",
        Short(h),
        Short(bob)
    );
    Made {
        shape: Shape::Pendulum { length: h, bob },
        size: h + bob,
        notes: vec![note],
    }
}

/// A plate of sides 2 : 1 with a body's mass and I_zz.
fn plate(mass: f64, izz: f64) -> Made {
    // a² + b² = 12 I_zz/M with a = 2b.
    let b = (12.0 * izz / (5.0 * mass)).sqrt();
    let note = format!(
        "a plate of {} × {} m (sides 2 : 1 assumed) with the mass and I_zz",
        Short(2.0 * b),
        Short(b)
    );
    Made {
        shape: Shape::Box {
            sides: [2.0 * b, b, 0.1 * b],
            axes: rows(&Matrix3::identity()),
        },
        size: 2.0 * b,
        notes: vec![note],
    }
}

/// The attitude quaternion of every row, as `orientation` reads it.
fn attitude(orientation: &Orientation, kept: &Kept) -> Result<[Vec<f64>; 4]> {
    let quaternion = |names: &[String; 4]| -> Result<[&[f64]; 4]> {
        let [q0, q1, q2, q3] = [0, 1, 2, 3].map(|k| kept.column(&names[k]));
        Ok([q0?, q1?, q2?, q3?])
    };
    Ok(match orientation {
        Orientation::Heading(psi) => about_axis(kept.column(psi)?, 2),
        Orientation::Pitch(theta) => about_axis(kept.column(theta)?, 1),
        Orientation::Quaternion(names) => unit(quaternion(names)?),
        Orientation::QuaternionAsIs(names) => quaternion(names)?.map(<[f64]>::to_vec),
        Orientation::EulerAngles(names) => {
            let [phi, theta, psi] = [0, 1, 2].map(|k| kept.column(&names[k]));
            from_euler_angles([phi?, theta?, psi?])
        }
    })
}

/// ω and H as the page draws them: the readout's columns of the rates (`shown` the columns the
/// readout shows) and the tensor.
fn vectors(spin: &Spin, shown: &[&str]) -> Result<Vectors> {
    let index = |name: &String| {
        (shown.iter().position(|shown| shown == name)).with_context(|| {
            format!("the view draws ω from the column {name}, which its readout does not show")
        })
    };
    let [p, q, r] = [0, 1, 2].map(|k| index(&spin.omega[k]));
    Ok(Vectors {
        omega: [p?, q?, r?],
        inertia: spin.inertia_about_g,
    })
}

/// The trail of a body whose reference point stays put (moves less than half its `size`: a
/// free spin) at the tip of body axis `axis`, three quarters of its size out; else of the
/// reference point.
fn tip_where_still(
    position: &[Vec<f64>; 3],
    size: f64,
    axis: usize,
    reference: &str,
) -> ([f64; 3], String) {
    let path = extent(&[&position[0], &position[1], &position[2]]);
    if path < 0.5 * size {
        let mut tip = [0.0; 3];
        tip[axis] = 0.75 * size;
        (tip, format!("tip of body {}", ["x", "y", "z"][axis]))
    } else {
        ([0.0; 3], reference.to_owned())
    }
}

/// The largest finite value of a column (−∞ for none): the deepest of a path, z down.
fn deepest(z: &[f64]) -> f64 {
    (z.iter())
        .filter(|z| z.is_finite())
        .fold(f64::NEG_INFINITY, |m, z| m.max(*z))
}

/// A matrix as rows.
fn rows(m: &Matrix3<f64>) -> [[f64; 3]; 3] {
    [0, 1, 2].map(|r| [m[(r, 0)], m[(r, 1)], m[(r, 2)]])
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

/// The solid cylinder with a body's mass and moments, along the principal axis nearest body x;
/// `None` where no cylinder has them.
fn cylinder(mass: f64, moments: [f64; 3], axes: Matrix3<f64>) -> Option<Made> {
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
    Some(Made {
        shape: Shape::Cylinder {
            length,
            diameter,
            axes: rows(&frame),
        },
        size: length.max(diameter),
        notes: vec![note],
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
        let q = from_euler_angles([&[0.3], &[-0.4], &[1.1]]);
        let from_q = UnitQuaternion::from_quaternion(eom::nalgebra::Quaternion::new(
            q[0][0], q[1][0], q[2][0], q[3][0],
        ))
        .to_rotation_matrix();
        let from_euler = Rotation3::from_euler_angles(0.3, -0.4, 1.1);
        assert!((from_q.matrix() - from_euler.matrix()).abs().max() < 1e-12);
    }

    /// A body that stays put (a free spin) trails the tip of the axis it spins about, three
    /// quarters of its size out; one that moves half its size or more, its reference point.
    #[test]
    fn a_body_that_stays_put_trails_the_tip_of_its_axis() {
        let path = |end: f64| [vec![0.0, end], vec![0.0, 0.0], vec![0.0, 0.0]];
        assert_eq!(
            tip_where_still(&path(0.9), 2.0, 2, "G"),
            ([0.0, 0.0, 1.5], "tip of body z".to_owned())
        );
        assert_eq!(
            tip_where_still(&path(1.0), 2.0, 2, "G"),
            ([0.0; 3], "G".to_owned())
        );
    }

    /// A flat disc has no solid cylinder of its moments (L² = 0): it is drawn as its box.
    #[test]
    fn a_cylinder_no_solid_has_is_drawn_as_the_box() {
        let disc = Solid {
            mass: 1.0,
            inertia_about_g: [[2.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        };
        let drawn = made(&Drawn::Cylinder(disc));
        assert!(
            matches!(drawn.shape, Shape::Box { .. }),
            "{:?}",
            drawn.shape
        );
        assert!(
            drawn.notes[0].starts_with("the uniform box"),
            "{:?}",
            drawn.notes
        );
        let rod = Solid {
            inertia_about_g: [[1.0, 0.0, 0.0], [0.0, 4.0, 0.0], [0.0, 0.0, 4.0]],
            ..disc
        };
        assert!(matches!(
            made(&Drawn::Cylinder(rod)).shape,
            Shape::Cylinder { .. }
        ));
    }
}
