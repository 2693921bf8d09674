//! The keys of an aircraft scene (`AircraftSceneFile`), in the order a template writes them.
//! The template's aircraft is the Stevens & Lewis F-16 of `scenes/f16.toml` with its tables
//! cut to the breakpoints around its trim at 502 ft/s (α 0 to 10°, the elevator ±12°, |β| to
//! 10°, the thrust at Mach 0.4 to 0.6 up to 10 000 ft), each value the book's: it trims and
//! runs a short doublet like the full F-16 (its lookups past the cut extend the end segments
//! where the full tables have more breakpoints), and a real scene gives the whole tables.

pub mod aerodynamics;
pub mod derivatives;

use crate::scene::reference::{Choices, Key, Kind, Required, SceneFamily, Shown};

/// Every key of an aircraft scene, a list a part, in the order a template writes them.
pub const ALL: &[&[Key]] = &[
    KEYS,
    aerodynamics::AERODYNAMICS,
    derivatives::DERIVATIVES,
    LATER,
];

const AIRCRAFT: &[SceneFamily] = &[SceneFamily::Kind("aircraft")];

/// What the reference says after the keys.
pub const NOTES: &str = "The state is in wind axes: `vt` (the airspeed), `alpha`, `beta` \
                         (rad), the Euler angles `phi`, `theta`, `psi` (rad), the body rates \
                         `p`, `q`, `r` (rad/s), `north`, `east`, `altitude` and the engine's \
                         `power` (percent); the controls are `throttle` (0 to 1), `elevator`, \
                         `aileron`, `rudder` (deg). Lengths and speeds are in the scene's units \
                         (`aircraft.units`). The tables are looked up linearly (bilinearly in \
                         two arguments) with the end segments extended past the ends, as the \
                         F-16's code does; their angles are in degrees.";

/// The keys of an aircraft scene before `[aerodynamics]`: `[aircraft]`, `[body]`, `[geometry]`,
/// `[engine]` (with [`aerodynamics::AERODYNAMICS`] and [`LATER`], every key, in order).
pub const KEYS: &[Key] = &[
    Key::shared(
        "title",
        AIRCRAFT,
        "\"An aircraft from eom new: the F-16 near its trim at 502 ft/s\"",
        Shown::Set,
    ),
    Key {
        path: "aircraft.units",
        families: AIRCRAFT,
        kind: Kind::Text(Choices::These(&["us", "si"])),
        required: Required::Yes,
        description: "The units of every length, mass and force of the scene: us (ft, slug, lbf) or si (m, kg, N); seconds, and degrees for the tables' angles and the surfaces, in both. Every output says its unit (summary.json's `units`).",
        example: "\"us\"",
        ..Key::BLANK
    },
    Key {
        path: "aircraft.atmosphere",
        families: AIRCRAFT,
        kind: Kind::Text(Choices::These(&["stevens-lewis", "standard-1976"])),
        required: Required::Yes,
        description: "The air: stevens-lewis, the air-data function the F-16's tables were published with (feet only), or standard-1976, the 1976 U.S. Standard Atmosphere to 20 km (geometric altitude).",
        example: "\"stevens-lewis\"",
        ..Key::BLANK
    },
    Key {
        path: "aircraft.aerodynamics",
        families: AIRCRAFT,
        kind: Kind::Text(Choices::These(&["stevens-lewis", "derivatives"])),
        required: Required::Yes,
        description: "The form of the aerodynamics: derivatives, a textbook's stability derivatives in `[aerodynamics.derivatives]` (scenes/navion.toml), or stevens-lewis, the F-16's build-up (C_x(α, δe) and C_m(α, δe), C_z(α) with its sideslip and elevator terms, C_y in β and the surfaces, C_l and C_n odd in β with the aileron's and rudder's increments, nine damping derivatives in α).",
        example: "\"stevens-lewis\"",
        ..Key::BLANK
    },
    Key {
        path: "aircraft.kinematics",
        families: AIRCRAFT,
        kind: Kind::Text(Choices::These(&["euler", "quaternion"])),
        default: "\"euler\"",
        description: "How a run carries the attitude: euler, the Euler angles (singular at θ = ±90°: a run that comes within 1° of it stops, saying so), or quaternion, a unit quaternion (q̇ = ½ q ⊗ (0, ω), its own proved program), for a loop or a vertical climb. The trim, the linear model and every row are in Euler angles either way (the rows' from the quaternion).",
        example: "\"quaternion\"",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "body.mass",
        families: AIRCRAFT,
        unit: "slug or kg",
        required: Required::Yes,
        description: "The mass.",
        example: "636.9426751592357",
        ..Key::BLANK
    },
    Key {
        path: "body.inertia",
        families: AIRCRAFT,
        kind: Kind::Numbers("3: I_xx, I_yy, I_zz"),
        unit: "slug ft² or kg m²",
        required: Required::Yes,
        description: "I_xx, I_yy, I_zz about G in body axes (x forward, z down).",
        example: "[9496.0, 55814.0, 63100.0]",
        ..Key::BLANK
    },
    Key {
        path: "body.products_of_inertia",
        families: AIRCRAFT,
        kind: Kind::Numbers("3: I_xy, I_yz, I_xz"),
        unit: "slug ft² or kg m²",
        default: "0, 0, 0",
        description: "I_xy, I_yz, I_xz: the tensor's off-diagonal entries in the chapter's sign (−∫xz dm; a text's J_xz = +982 is −982 here, or give it as printed in body.products_of_inertia_integrals). An aircraft is symmetric about its xz-plane: I_xy and I_yz must be 0. The tensor must be one a rigid body can have.",
        example: "[0.0, 0.0, -982.0]",
        ..Key::BLANK
    },
    Key {
        path: "body.products_of_inertia_integrals",
        families: AIRCRAFT,
        kind: Kind::Numbers("3: ∫xy dm, ∫yz dm, ∫xz dm"),
        unit: "slug ft² or kg m²",
        default: "0, 0, 0",
        description: "The same products as the integrals ∫xy dm, ∫yz dm, ∫xz dm, typed as Etkin, Nelson and Stevens print them (Etkin's 747: I_zx = −0.212e7 kg m²; Stevens's J_xz = +982): the tensor's entries are their negatives, and the run's report prints the tensor eom uses. Give this key or body.products_of_inertia, not both.",
        example: "[0.0, 0.0, 982.0]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "body.gravity",
        families: AIRCRAFT,
        unit: "ft/s² or m/s²",
        required: Required::Yes,
        description: "Gravity, constant (flat Earth).",
        example: "32.17",
        ..Key::BLANK
    },
    Key {
        path: "geometry.area",
        families: AIRCRAFT,
        unit: "ft² or m²",
        required: Required::Yes,
        description: "The wing's reference area S.",
        example: "300.0",
        ..Key::BLANK
    },
    Key {
        path: "geometry.span",
        families: AIRCRAFT,
        unit: "ft or m",
        required: Required::Yes,
        description: "The span b (the rolling and yawing moments' length, and b/2V for the rates).",
        example: "30.0",
        ..Key::BLANK
    },
    Key {
        path: "geometry.chord",
        families: AIRCRAFT,
        unit: "ft or m",
        required: Required::Yes,
        description: "The mean aerodynamic chord c̄ (the pitching moment's length, and c̄/2V).",
        example: "11.32",
        ..Key::BLANK
    },
    Key {
        path: "geometry.length",
        families: AIRCRAFT,
        unit: "ft or m",
        required: Required::No,
        description: "The fuselage's length, for the view alone (view.html draws the fuselage that long and a tenth of it across, the wings of the span and chord, the tail a third of the span); without it the view draws the fuselage as long as the span and says so.",
        example: "49.0",
        ..Key::BLANK
    },
    Key {
        path: "geometry.xcg",
        families: AIRCRAFT,
        unit: "-",
        required: Required::Yes,
        description: "G, as a fraction of c̄ aft of its leading edge; the moments are carried from the tables' reference to G.",
        example: "0.30",
        ..Key::BLANK
    },
    Key {
        path: "geometry.xcg_reference",
        families: AIRCRAFT,
        unit: "-",
        required: Required::Yes,
        description: "Where the moment tables are given, likewise.",
        example: "0.35",
        ..Key::BLANK
    },
    Key {
        path: "engine.rotor_momentum",
        families: AIRCRAFT,
        unit: "slug ft²/s or kg m²/s",
        required: Required::Yes,
        description: "The engine rotor's angular momentum along body x (a constant gyroscopic moment −ω × h_E).",
        example: "160.0",
        ..Key::BLANK
    },
    Key {
        path: "engine.altitude",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "ft or m",
        required: Required::When("for thrust tables (without engine.thrust)"),
        description: "The thrust tables' altitudes, strictly increasing.",
        example: "[0.0, 10000.0]",
        ..Key::BLANK
    },
    Key {
        path: "engine.mach",
        families: AIRCRAFT,
        kind: Kind::Numbers("breakpoints"),
        unit: "-",
        required: Required::When("for thrust tables (without engine.thrust)"),
        description: "Their Mach numbers, strictly increasing.",
        example: "[0.4, 0.6]",
        ..Key::BLANK
    },
    Key {
        path: "engine.idle",
        families: AIRCRAFT,
        kind: Kind::Numbers("rows, one per altitude"),
        unit: "lbf or N",
        required: Required::When("for thrust tables (without engine.thrust)"),
        description: "Thrust at idle power, [altitude][mach]; from 0 to 50 % power the thrust goes from idle to military.",
        example: "[[60.0, -1020.0], [25.0, -710.0]]",
        ..Key::BLANK
    },
    Key {
        path: "engine.military",
        families: AIRCRAFT,
        kind: Kind::Numbers("rows, one per altitude"),
        unit: "lbf or N",
        required: Required::When("for thrust tables (without engine.thrust)"),
        description: "Thrust at military power (100 % dry, power 50 %).",
        example: "[[12610.0, 12640.0], [9312.0, 9839.0]]",
        ..Key::BLANK
    },
    Key {
        path: "engine.maximum",
        families: AIRCRAFT,
        kind: Kind::Numbers("rows, one per altitude"),
        unit: "lbf or N",
        required: Required::When("for thrust tables (without engine.thrust)"),
        description: "Thrust at maximum power (full afterburner, power 100 %); the throttle's gearing and the power's lag are the F-16's (commanded power 64.94 δt to δt = 0.77, 217.38 δt − 117.38 above; a first-order lag whose time constant depends on the change, crossing the afterburner's threshold at 50 %).",
        example: "[[22700.0, 24240.0], [16860.0, 18910.0]]",
        ..Key::BLANK
    },
    Key {
        path: "engine.thrust",
        families: AIRCRAFT,
        unit: "lbf or N",
        required: Required::When("for a constant thrust (instead of the tables)"),
        description: "A thrust that does not change with speed or altitude, as textbooks' small-perturbation models take a light aircraft's: T = thrust · power/100, the power lagging 100 · throttle (percent).",
        example: "400.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "engine.time_constant_s",
        families: AIRCRAFT,
        unit: "s",
        required: Required::When("with engine.thrust"),
        description: "The constant thrust's power lag: ṗ = (100 · throttle − power)/time_constant_s.",
        example: "1.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
];

/// The keys after `[aerodynamics]`: the limits, the trim, the manoeuvres, the integrator, the
/// output, the sweep and the Monte Carlo.
pub const LATER: &[Key] = &[
    Key {
        path: "limits.alpha_deg",
        families: AIRCRAFT,
        kind: Kind::Numbers("2: lowest, highest"),
        unit: "deg",
        required: Required::Yes,
        description: "α's range where the tables hold data: a trim outside it is refused (the lookups past it extend the end segments).",
        example: "[-10.0, 45.0]",
        ..Key::BLANK
    },
    Key {
        path: "limits.elevator_deg",
        families: AIRCRAFT,
        unit: "deg",
        required: Required::Yes,
        description: "The elevator's deflection limit, ±: a trim or a manoeuvre beyond it is refused.",
        example: "25.0",
        ..Key::BLANK
    },
    Key {
        path: "limits.aileron_deg",
        families: AIRCRAFT,
        unit: "deg",
        required: Required::Yes,
        description: "The aileron's.",
        example: "21.5",
        ..Key::BLANK
    },
    Key {
        path: "limits.rudder_deg",
        families: AIRCRAFT,
        unit: "deg",
        required: Required::Yes,
        description: "The rudder's.",
        example: "30.0",
        ..Key::BLANK
    },
    Key {
        path: "trim.speed",
        families: AIRCRAFT,
        unit: "ft/s or m/s",
        required: Required::Yes,
        description: "The true airspeed of the steady flight every manoeuvre starts from (and `eom linear` linearises at): throttle, elevator, α, aileron, rudder and β are solved for so that V̇, α̇, β̇, ṗ, q̇, ṙ vanish, the rest following from the condition (Stevens & Lewis §3.6); a condition that needs a throttle beyond 0 to 1, an α beyond the tables or a surface beyond its limit is refused, naming it.",
        example: "502.0",
        ..Key::BLANK
    },
    Key {
        path: "trim.altitude",
        families: AIRCRAFT,
        unit: "ft or m",
        required: Required::Yes,
        description: "Its altitude.",
        example: "0.0",
        ..Key::BLANK
    },
    Key {
        path: "trim.climb_angle_rad",
        families: AIRCRAFT,
        unit: "rad",
        default: "0: level",
        description: "The flight-path angle γ, positive climbing (θ from the rate-of-climb constraint).",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "trim.turn_rate_rad_s",
        families: AIRCRAFT,
        unit: "rad/s",
        default: "0: straight",
        description: "The turn rate ψ̇ of a coordinated turn (φ from the coordination constraint, p, q, r from ψ̇).",
        example: "0.3",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "trim.pull_up_rate_rad_s",
        families: AIRCRAFT,
        unit: "rad/s",
        default: "0",
        description: "The pitch rate q of a steady pull-up (no turn with it).",
        example: "0.1",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].name",
        families: AIRCRAFT,
        kind: Kind::Text(Choices::Free),
        default: "its kind",
        description: "The manoeuvre's output folder: letters, digits, _ - ., each name once.",
        example: "\"doublet\"",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].kind",
        families: AIRCRAFT,
        kind: Kind::Text(Choices::These(&[
            "elevator_doublet",
            "aileron_step",
            "rudder_kick",
            "throttle_step",
            "pull_up",
        ])),
        required: Required::Yes,
        description: "From the trim: elevator_doublet, the elevator +amount for width_s then −amount for width_s, then back; aileron_step and throttle_step, +amount from start_s on; rudder_kick, +amount for width_s (the Dutch roll's period and damping are read from the yaw rate after it, beside the linear model's); pull_up, the elevator −amount (nose up) from start_s on. Each gives its peak and least load factor, α, β and roll-rate excursions, and its end speed and altitude change.",
        example: "\"elevator_doublet\"",
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].amount",
        families: AIRCRAFT,
        unit: "deg or -",
        required: Required::Yes,
        description: "The change from the trim: degrees of a surface, or of throttle (0 to 1). A command beyond a limit, or a throttle beyond 0 to 1, is refused.",
        example: "1.0",
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].start_s",
        families: AIRCRAFT,
        unit: "s",
        default: "1",
        description: "When the controls first move.",
        example: "1.0",
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].width_s",
        families: AIRCRAFT,
        unit: "s",
        default: "1",
        required: Required::When("for elevator_doublet and rudder_kick"),
        description: "A doublet's half and a kick's pulse.",
        example: "1.0",
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].duration_s",
        families: AIRCRAFT,
        unit: "s",
        required: Required::Yes,
        description: "How long the run lasts.",
        example: "5.0",
        ..Key::BLANK
    },
    Key::shared("integrator.method", AIRCRAFT, "\"rk4\"", Shown::Set),
    Key::shared("integrator.step", AIRCRAFT, "0.01", Shown::Set),
    Key::shared("integrator.rtol", AIRCRAFT, "1e-9", Shown::Commented),
    Key::shared("integrator.atol", AIRCRAFT, "1e-9", Shown::Commented),
    Key::shared(
        "integrator.max_steps",
        AIRCRAFT,
        "1_000_000",
        Shown::Commented,
    ),
    Key::shared(
        "integrator.stop_when",
        AIRCRAFT,
        "\"altitude < -500\"",
        Shown::Commented,
    ),
    Key {
        path: "output.every",
        families: AIRCRAFT,
        unit: "s",
        default: "the step",
        required: Required::When("for an adaptive method"),
        description: "Trajectory rows at exactly t = k·every, and a row at each change of the controls.",
        example: "0.05",
        ..Key::BLANK
    },
    Key {
        path: "linear.at.*",
        families: AIRCRAFT,
        kind: Kind::Table("state entries and controls by name, and values"),
        description: "The operating point of `eom linear`, where it differs from the trim: state entries (vt, alpha, …, power) and controls (throttle, elevator, aileron, rudder) by name, in the scene's units and radians (the surfaces in degrees).",
        example: "alpha = 0.04",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "linear.trim",
        families: AIRCRAFT,
        kind: Kind::Names("state entries or controls"),
        description: "Free variables of `eom linear`, solved for by Newton's method so that the reduced state is in equilibrium.",
        example: "[\"alpha\", \"elevator\"]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "linear.outputs",
        families: AIRCRAFT,
        kind: Kind::Names("state entries"),
        description: "Outputs of the linear model (y = C x in linear.json and linear.mat): state entries by name, each in the reduced state; by default every entry of it.",
        example: "[\"alpha\", \"q\"]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key::shared(
        "sweep.*",
        AIRCRAFT,
        "\"geometry.xcg\" = [0.25, 0.30, 0.35]",
        Shown::Commented,
    ),
    // [uncertainty]
    Key::shared("uncertainty.cases", AIRCRAFT, "1000", Shown::Commented),
    Key::shared("uncertainty.seed", AIRCRAFT, "1", Shown::Commented),
    Key::shared(
        "uncertainty.vary.*",
        AIRCRAFT,
        "\"geometry.xcg\" = { distribution = \"uniform\", low = 0.25, high = 0.35 }",
        Shown::Commented,
    ),
];
