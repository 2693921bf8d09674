//! A catalog body's `[loads]` keys: gravity, buoyancy, forces and moments (constant or time
//! tables, in body or space axes, at G or at a point), linear and quadratic damping.

use super::*;

/// The `[loads]` keys, in the order a template writes them.
pub static LOADS: &[Key] = &[
    // [loads]: what is left out is zero.
    Key {
        path: "loads.gravity",
        families: &[SPATIAL],
        unit: "m/s²",
        frame: Frame::Space,
        default: "0",
        description: "g: the weight Mg acts at G along +Z, down. (The pendulum and the top \
                      carry their own, body.g.)",
        example: "9.81",
        ..Key::BLANK
    },
    Key {
        path: "loads.buoyancy",
        families: &[SPATIAL],
        unit: "N",
        frame: Frame::Space,
        default: "0",
        description: "B, acting along −Z (up) at loads.buoyancy_centre.",
        example: "9.81",
        ..Key::BLANK
    },
    Key {
        path: "loads.buoyancy_centre",
        families: &[SPATIAL],
        kind: Kind::Numbers("3: x, y, z"),
        unit: "m",
        frame: Frame::Body,
        default: "zero",
        description: "The centre of buoyancy, from G.",
        example: "[0.0, 0.0, -0.05]",
        ..Key::BLANK
    },
    Key {
        path: "loads.force_body",
        families: &[SPATIAL],
        kind: Kind::Numbers("3: F_x, F_y, F_z"),
        unit: "N",
        frame: Frame::Body,
        default: "zero",
        description: "A force at G (or at force_body_at) that turns with the body (a thrust). Constant, or a time table { times = [s…], values = […], interpolation = `step` | `linear` }: the end values hold outside it, and the run is cut at its times so no step straddles a change.",
        example: "[0.5, 0.0, 0.0]",
        ..Key::BLANK
    },
    Key {
        path: "loads.force_body",
        families: PLANAR,
        kind: Kind::Numbers("2: F_x, F_y"),
        unit: "N",
        frame: Frame::Body,
        default: "zero",
        description: "A force at the body origin (or at force_body_at) that turns with the \
                      body (a thrust). Constant, or a time table { times = [s…], values = […], interpolation = `step` | `linear` }: the end values hold outside it, and the run is cut at its times so no step straddles a change.",
        example: "[1.0, 0.0]",
        ..Key::BLANK
    },
    Key {
        path: "loads.force_space",
        families: &[SPATIAL],
        kind: Kind::Numbers("3: F_X, F_Y, F_Z"),
        unit: "N",
        frame: Frame::Space,
        default: "zero",
        description: "A force at G (or at force_space_at) fixed in space (a wind); constant, \
                      it has a potential. Constant, or a time table { times = [s…], values = […], interpolation = `step` | `linear` }: the end values hold outside it, and the run is cut at its times so no step straddles a change.",
        example: "[0.0, 0.0, 0.0]",
        ..Key::BLANK
    },
    Key {
        path: "loads.force_space",
        families: PLANAR,
        kind: Kind::Numbers("2: F_X, F_Y"),
        unit: "N",
        frame: Frame::Space,
        default: "zero",
        description: "A force at the body origin (or at force_space_at) fixed in space (a \
                      wind); constant, it has a potential. Constant, or a time table { times = [s…], values = […], interpolation = `step` | `linear` }: the end values hold outside it, and the run is cut at its times so no step straddles a change.",
        example: "[0.0, 0.5]",
        ..Key::BLANK
    },
    Key {
        path: "loads.force_body_at",
        families: &[SPATIAL],
        kind: Kind::Numbers("3: x, y, z"),
        unit: "m",
        frame: Frame::Body,
        default: "G",
        description: "Where force_body acts, from G: it adds the moment r_P × F about G (4.2). \
                      Only with force_body.",
        example: "[0.5, 0.0, 0.0]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "loads.force_body_at",
        families: PLANAR,
        kind: Kind::Numbers("2: x, y"),
        unit: "m",
        frame: Frame::Body,
        default: "the body origin",
        description: "Where force_body acts, from the body origin: it adds the moment r_P × F. \
                      Only with force_body.",
        example: "[1.0, 0.0]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "loads.force_space_at",
        families: &[SPATIAL],
        kind: Kind::Numbers("3: x, y, z"),
        unit: "m",
        frame: Frame::Body,
        default: "G",
        description: "Where force_space acts, from G, in body axes: it adds r_P × F about G \
                      and keeps the force's potential. Only with force_space.",
        example: "[0.5, 0.0, 0.0]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "loads.force_space_at",
        families: PLANAR,
        kind: Kind::Numbers("2: x, y"),
        unit: "m",
        frame: Frame::Body,
        default: "the body origin",
        description: "Where force_space acts, from the body origin, in body axes. Only with \
                      force_space.",
        example: "[1.0, 0.0]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "loads.moment_body",
        families: &[SPATIAL],
        kind: Kind::Numbers("3: M_x, M_y, M_z"),
        unit: "N m",
        frame: Frame::Body,
        default: "zero",
        description: "A moment about G. Constant, or a time table { times = [s…], values = […], interpolation = `step` | `linear` }: the end values hold outside it, and the run is cut at its times so no step straddles a change.",
        example: "[0.0, 0.0, 0.0]",
        ..Key::BLANK
    },
    Key {
        path: "loads.moment_body",
        families: &[TOP],
        kind: Kind::Numbers("3: M_x, M_y, M_z"),
        unit: "N m",
        frame: Frame::Body,
        default: "zero",
        description: "A moment about the pivot. Constant, or a time table { times = [s…], values = […], interpolation = `step` | `linear` }: the end values hold outside it, and the run is cut at its times so no step straddles a change.",
        example: "[0.0, 0.0, 0.0]",
        ..Key::BLANK
    },
    Key {
        path: "loads.moment_space",
        families: &[SPATIAL],
        kind: Kind::Numbers("3: M_X, M_Y, M_Z"),
        unit: "N m",
        frame: Frame::Space,
        default: "zero",
        description: "A moment about G fixed in space. Constant, or a time table { times = [s…], values = […], interpolation = `step` | `linear` }: the end values hold outside it, and the run is cut at its times so no step straddles a change.",
        example: "[0.0, 0.0, 0.0]",
        ..Key::BLANK
    },
    Key {
        path: "loads.moment",
        families: PLANAR_AND_PENDULUM,
        unit: "N m",
        default: "0",
        description: "A moment about the vertical (planar) or about the pivot (pendulum); \
                      constant, it has a potential. Constant, or a time table { times = [s…], values = […], interpolation = `step` | `linear` }: the end values hold outside it, and the run is cut at its times so no step straddles a change.",
        example: "0.1",
        ..Key::BLANK
    },
    Key {
        path: "loads.linear_damping",
        families: &[SPATIAL],
        kind: Kind::Numbers("6: on u, v, w, p, q, r"),
        unit: "N s/m on u, v, w; N m s on p, q, r",
        frame: Frame::Body,
        default: "zero",
        description: "Each velocity's load −dᵢxᵢ (forces on u, v, w, moments on p, q, r); no \
                      coefficient negative.",
        example: "[1.0, 2.0, 2.0, 0.1, 0.1, 0.1]",
        ..Key::BLANK
    },
    Key {
        path: "loads.linear_damping",
        families: PLANAR,
        kind: Kind::Numbers("3: on u, v, r"),
        unit: "N s/m on u, v; N m s on r",
        frame: Frame::Body,
        default: "zero",
        description: "Each velocity's load −dᵢxᵢ; no coefficient negative.",
        example: "[1.0, 2.0, 0.5]",
        ..Key::BLANK
    },
    Key {
        path: "loads.linear_damping",
        families: &[PENDULUM],
        kind: Kind::Numbers("1: on θ̇"),
        unit: "N m s",
        default: "zero",
        description: "The moment −dθ̇ about the pivot; not negative.",
        example: "[0.05]",
        ..Key::BLANK
    },
    Key {
        path: "loads.linear_damping",
        families: &[TOP],
        kind: Kind::Numbers("3: on p, q, r"),
        unit: "N m s",
        frame: Frame::Body,
        default: "zero",
        description: "Each rate's moment −dᵢωᵢ; no coefficient negative.",
        example: "[0.0, 0.0, 0.001]",
        ..Key::BLANK
    },
    Key {
        path: "loads.quadratic_damping",
        families: &[SPATIAL],
        kind: Kind::Numbers("6: on u, v, w, p, q, r"),
        unit: "N s²/m² on u, v, w; N m s² on p, q, r",
        frame: Frame::Body,
        default: "zero",
        description: "Each velocity's load −dᵢxᵢ|xᵢ|; no coefficient negative.",
        example: "[2.0, 10.0, 10.0, 0.1, 0.5, 0.5]",
        ..Key::BLANK
    },
    Key {
        path: "loads.quadratic_damping",
        families: PLANAR,
        kind: Kind::Numbers("3: on u, v, r"),
        unit: "N s²/m² on u, v; N m s² on r",
        frame: Frame::Body,
        default: "zero",
        description: "Each velocity's load −dᵢxᵢ|xᵢ|; no coefficient negative.",
        example: "[0.5, 5.0, 1.0]",
        ..Key::BLANK
    },
    Key {
        path: "loads.quadratic_damping",
        families: &[PENDULUM],
        kind: Kind::Numbers("1: on θ̇"),
        unit: "N m s²",
        default: "zero",
        description: "The moment −dθ̇|θ̇| about the pivot; not negative.",
        example: "[0.01]",
        ..Key::BLANK
    },
    Key {
        path: "loads.quadratic_damping",
        families: &[TOP],
        kind: Kind::Numbers("3: on p, q, r"),
        unit: "N m s²",
        frame: Frame::Body,
        default: "zero",
        description: "Each rate's moment −dᵢωᵢ|ωᵢ|; no coefficient negative.",
        example: "[0.0, 0.0, 0.0]",
        ..Key::BLANK
    },
];
