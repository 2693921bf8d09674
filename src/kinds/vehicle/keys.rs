//! The keys of a vehicle scene (`eom::kinds::vehicle::scene::VehicleSceneFile`), in the order a
//! template writes them. The template's vehicle is REMUS on Prestero's table, as in
//! `scenes/remus100.toml` (its sources and the readings that differ are said there), with a
//! short turn so that the template runs in a moment.

use crate::scene::reference::{Choices, Key, Kind, Required, SceneFamily, Shown};

const VEHICLE: &[SceneFamily] = &[SceneFamily::Kind("vehicle")];

/// A fin's keys, for `[rudder]` and `[stern_planes]`.
macro_rules! fin_keys {
    ($table:literal, $what:literal) => {
        [
            Key {
                path: concat!($table, ".max_deg"),
                families: VEHICLE,
                unit: "deg",
                default: "no limit",
                description: concat!(
                    "Where the ",
                    $what,
                    " saturate(s). A manoeuvre's command beyond it (rudder_deg, \
                     stern_planes_deg, a zigzag's fin_deg) is refused: it would run at the \
                     stop while labelled and judged as asked; the autopilots' commands stop \
                     there."
                ),
                example: "13.6",
                shown: Shown::Commented,
                ..Key::BLANK
            },
            Key {
                path: concat!($table, ".max_rate_deg_s"),
                families: VEHICLE,
                unit: "deg/s",
                default: "no limit",
                description: concat!(
                    "The ",
                    $what,
                    "' rate limit; it acts on the lag's rate, so it needs ",
                    $table,
                    ".time_constant_s. Where it starts or stops acting, the rate has a kink, \
                     which the run locates as an event (so every method keeps its order)."
                ),
                example: "20.0",
                shown: Shown::Commented,
                ..Key::BLANK
            },
            Key {
                path: concat!($table, ".time_constant_s"),
                families: VEHICLE,
                unit: "s",
                default: "no lag: at the command at once",
                description: concat!("The ", $what, "' first-order lag."),
                example: "0.1",
                shown: Shown::Commented,
                ..Key::BLANK
            },
        ]
    };
}

const RUDDER: [Key; 3] = fin_keys!("rudder", "rudder");
const STERN_PLANES: [Key; 3] = fin_keys!("stern_planes", "stern planes");

/// Every key of a vehicle scene.
pub const KEYS: &[Key] = &[
    Key::shared(
        "title",
        VEHICLE,
        "\"A vehicle from eom new: REMUS 100 on Prestero's table\"",
        Shown::Set,
    ),
    Key {
        path: "model.family",
        families: VEHICLE,
        kind: Kind::Text(Choices::These(&["vehicle"])),
        required: Required::Yes,
        description: "A vehicle runs the six equations about its table's origin O; `vehicle` \
                      with a [hydrodynamics] table is what makes a scene a vehicle scene.",
        example: "\"vehicle\"",
        ..Key::BLANK
    },
    Key {
        path: "body.mass",
        families: VEHICLE,
        unit: "kg",
        required: Required::Yes,
        description: "M, the vehicle's mass. body.weight / body.mass must be gravity at the \
                      Earth's surface (9.780 to 9.832 m/s²) to the rounding of the two numbers \
                      as written: a payload in one and not the other is refused.",
        example: "30.48",
        ..Key::BLANK
    },
    Key {
        path: "body.weight",
        families: VEHICLE,
        unit: "N",
        required: Required::Yes,
        description: "W, acting at G, vertical in space axes (tables give it apart from M).",
        example: "299.0",
        ..Key::BLANK
    },
    Key {
        path: "body.buoyancy",
        families: VEHICLE,
        unit: "N",
        required: Required::Yes,
        description: "B, acting at the centre of buoyancy, up in space axes.",
        example: "299.0",
        ..Key::BLANK
    },
    Key {
        path: "body.centre_of_gravity",
        families: VEHICLE,
        kind: Kind::Numbers("3: x_G, y_G, z_G"),
        unit: "m",
        frame: crate::scene::reference::Frame::Body,
        required: Required::Yes,
        description: "r_G, from the table's origin O.",
        example: "[0.0, 0.0, 0.0196]",
        ..Key::BLANK
    },
    Key {
        path: "body.centre_of_buoyancy",
        families: VEHICLE,
        kind: Kind::Numbers("3: x_B, y_B, z_B"),
        unit: "m",
        frame: crate::scene::reference::Frame::Body,
        required: Required::Yes,
        description: "r_B, from O.",
        example: "[0.0, 0.0, 0.0]",
        ..Key::BLANK
    },
    Key {
        path: "body.inertia",
        families: VEHICLE,
        kind: Kind::Numbers("3: I_xx, I_yy, I_zz"),
        unit: "kg m²",
        frame: crate::scene::reference::Frame::Body,
        required: Required::Yes,
        description: "The moments of inertia about the point body.inertia_about names; with \
                      body.products_of_inertia, the tensor [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], \
                      [Ixz, Iyz, Izz]], which must be physical: positive definite, each moment \
                      at most the sum of the other two (and about O, its tensor about G too).",
        example: "[0.177, 3.45, 3.45]",
        ..Key::BLANK
    },
    Key {
        path: "body.products_of_inertia",
        families: VEHICLE,
        kind: Kind::Numbers("3: I_xy, I_yz, I_xz"),
        unit: "kg m²",
        frame: crate::scene::reference::Frame::Body,
        default: "[0, 0, 0]: principal axes along the body axes",
        description: "The products of inertia, the tensor's off-diagonal entries with the \
                      chapter's sign, Ixy = −∫xy dm (4.12–4.14), as a catalog scene writes them \
                      in body.inertia, so H = [I]ω. Fossen's tables (MSS) write Ixy = ∫xy dm and \
                      −Ixy in the tensor: enter those with their sign changed. Products that \
                      are zero are pruned from the model (Ixy = Iyz = 0: the x–z plane of \
                      symmetry; all zero: principal axes).",
        example: "[0.0, 0.0, 0.0]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "body.inertia_about",
        families: VEHICLE,
        kind: Kind::Text(Choices::These(&["G", "origin"])),
        default: "G",
        description: "The point body.inertia is about: G, carried to O by Steiner (4.23), or \
                      the table's origin O, used as given.",
        // Prestero's REMUS moments are about O (data/README.md).
        example: "\"origin\"",
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.convention",
        families: VEHICLE,
        kind: Kind::Text(Choices::These(&["prestero", "fossen"])),
        required: Required::Yes,
        description: "How the names are read. fossen: every factor written, |x| an absolute \
                      value (Yv|v| = v|v|, Xuu = u²). prestero: a doubled velocity in its \
                      load's plane is x|x| (Xuu = u|u|, Yvv = v|v|, Nrr = r|r|), Xqq and Xrr \
                      are q², r², a doubled u before controls only is u² (Yuudr); any other \
                      repetition is refused as ambiguous.",
        example: "\"prestero\"",
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.added_mass_coriolis",
        families: VEHICLE,
        kind: Kind::Text(Choices::These(&["folded", "derived"])),
        required: Required::Yes,
        description: "folded: the table's cross terms already hold the added mass's Coriolis \
                      and centripetal terms (Prestero's Xwq, Ywp, Mrp, …), and summary.json \
                      shows each against what the added mass implies. derived: eom adds \
                      Kirchhoff's terms from T_A = ½νᵀM_Aν.",
        example: "\"folded\"",
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.units",
        families: VEHICLE,
        kind: Kind::Text(Choices::These(&["dimensional", "prime"])),
        default: "\"dimensional\"",
        description: "The units of the added mass and of the coefficients (the body is in SI \
                      always). dimensional: SI. prime: the standard submarine equations' prime \
                      system, as Healey & Lienard give the NPS AUV II and Fossen's npsauv.m \
                      scales it, with U = u the surge velocity: a term of j velocity factors, a \
                      of them angular, adds ½ρL^(2 + a + m)·u^(2 − j) times its coefficient and \
                      its product (m = 1 for K, M, N), so Yv adds ½ρL²·Yv·u·v, Kp ½ρL⁴·Kp·u·p, \
                      Ydr ½ρL²·Ydr·u²·dr; an added-mass entry is ½ρL^(3 + m + a) times its \
                      value. A term of more than two velocity factors is refused, and two \
                      names of one product once u is written out (Yv, Yuv) are one term.",
        example: "\"prime\"",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.density",
        families: VEHICLE,
        unit: "kg/m³",
        required: Required::When("in a prime table (a dimensional one refuses it)"),
        description: "ρ, the water's density, of the prime system.",
        example: "1025.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.length",
        families: VEHICLE,
        unit: "m",
        required: Required::When("in a prime table (a dimensional one refuses it)"),
        description: "L, the prime system's unit of length (the NPS AUV II: 5.3 m).",
        example: "5.3",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.added_mass.*",
        families: VEHICLE,
        kind: Kind::Table("added-mass names and numbers"),
        unit: "kg, kg m, kg m² (or prime: hydrodynamics.units)",
        required: Required::Yes,
        description: "The acceleration derivatives: a load letter, a velocity, `dot` (Xudot, \
                      Yrdot, …); M_A = −(these), symmetric, each filling its partner; both \
                      names of a pair (Yrdot, Nvdot) must agree. M_RB + M_A must be positive \
                      definite (an error names the row's entries otherwise).",
        example: "Xudot = -0.93\nYvdot = -35.5\nYrdot = 1.93\nZwdot = -35.5\nZqdot = -1.93\n\
                  Kpdot = -0.0704\nMwdot = -1.93\nMqdot = -4.88\nNvdot = 1.93\nNrdot = -4.88",
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.coefficients.*",
        families: VEHICLE,
        kind: Kind::Table("coefficient names and numbers"),
        unit: "SI (or prime: hydrodynamics.units)",
        required: Required::Yes,
        description: "The terms to model, and only those: a load letter (X, Y, Z, K, M, N) and \
                      the factors of its term, read under the convention: the velocities u, \
                      v, w, p, q, r, the controls dr (rudder) and ds (stern planes), 0 for a \
                      constant. An unknown or ambiguous name, or two names of one term, is \
                      refused naming it.",
        example: "Xuu = -1.62\nXwq = -35.5\nXqq = -1.93\nXvr = 35.5\nXrr = -1.93\n\
                  Yvv = -1310.0\nYrr = 0.632\nYuv = -28.6\nYwp = 35.5\nYur = 5.22\n\
                  Ypq = 1.93\nYuudr = 9.64\nZww = -131.0\nZqq = -0.632\nZuw = -28.6\n\
                  Zuq = -5.22\nZvp = -35.5\nZrp = 1.93\nZuuds = -9.64\nKpp = -0.130\n\
                  Mww = 3.18\nMqq = -188.0\nMuw = 24.0\nMuq = -2.0\nMvp = -1.93\n\
                  Mrp = 4.86\nMuuds = -6.15\nNvv = -3.18\nNrr = -94.0\nNuv = -24.0\n\
                  Nur = -2.0\nNwp = -1.93\nNpq = -4.86\nNuudr = -6.15",
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.cross_flow.stations",
        families: VEHICLE,
        kind: Kind::Numbers("one per strip"),
        unit: "m",
        required: Required::When("with [hydrodynamics.cross_flow]"),
        description: "x_i, each strip's station along body x from O. The cross-flow drag (eom::kinds::vehicle::cross_flow, after npsauv.m's strips): at each strip the local cross flow a = v + x r, b = w − x q gives the force −½ρΔx(C_dy H a² + C_dz B b²)(a, b)/√(a² + b²) in y and z, and the loads about O are these forces and their moments (the pitch moment −Σ x F_z: npsauv.m's reads w + x q there, and the scene follows the moment of its own forces). Not a polynomial: computed beside the proved program, which reads its loads as its applied loads, with its derivatives in the Jacobian.",
        example: "[-0.6, 0.0, 0.6]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.cross_flow.lengths",
        families: VEHICLE,
        kind: Kind::Numbers("one per strip"),
        unit: "m",
        required: Required::When("with [hydrodynamics.cross_flow]"),
        description: "Δx_i, each strip's length, positive.",
        example: "[0.6, 0.6, 0.6]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.cross_flow.heights",
        families: VEHICLE,
        kind: Kind::Numbers("one per strip"),
        unit: "m",
        required: Required::When("with [hydrodynamics.cross_flow]"),
        description: "H_i, each strip's height, the area the sway flow meets per length, positive.",
        example: "[0.19, 0.19, 0.19]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.cross_flow.breadths",
        families: VEHICLE,
        kind: Kind::Numbers("one per strip"),
        unit: "m",
        required: Required::When("with [hydrodynamics.cross_flow]"),
        description: "B_i, each strip's breadth, the area the heave flow meets per length, positive.",
        example: "[0.19, 0.19, 0.19]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.cross_flow.sway_coefficient",
        families: VEHICLE,
        required: Required::When("with [hydrodynamics.cross_flow]"),
        description: "C_dy, the drag coefficient of the sway flow, positive.",
        example: "0.5",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.cross_flow.heave_coefficient",
        families: VEHICLE,
        required: Required::When("with [hydrodynamics.cross_flow]"),
        description: "C_dz, the drag coefficient of the heave flow, positive.",
        example: "0.6",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.cross_flow.density",
        families: VEHICLE,
        unit: "kg/m³",
        default: "hydrodynamics.density",
        required: Required::When("in a dimensional table"),
        description: "ρ of the drag: the prime system's unless given.",
        example: "1025.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "propeller.law",
        families: VEHICLE,
        kind: Kind::Text(Choices::These(&["constant", "healey_lienard"])),
        default: "constant",
        description: "What gives the propeller's loads. constant: propeller.thrust and \
                      propeller.torque as given. healey_lienard: the NPS AUV II's law in the \
                      propeller's rate as Healey & Lienard (1993) and Fossen's npsauv.m give \
                      it, in the prime system (hydrodynamics.units = \"prime\"): prop = \
                      advance·n/u (n in rad/s), the thrust ½ρL²·drag_coefficient·(advance·n)² \
                      for u > 0 (the law's resistance, ½ρL²C_d0u², is the table's Xuu), and \
                      ε = −1 + (√(C_t + 1) − 1)/(√(C_t1 + 1) − 1), C_t = \
                      thrust_coefficient·L²·prop|prop|/2, C_t1 at prop = 1: the factor `n` of \
                      the table's terms (Zqn is u·q·ε), computed beside the proved program; ε = \
                      0 at the cruise u = advance·n. The law holds for u > 0: at u ≤ 0 the run \
                      stops on its guard against values that are not finite.",
        example: "\"constant\"",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "propeller.thrust",
        families: VEHICLE,
        unit: "N",
        frame: crate::scene::reference::Frame::Body,
        required: Required::When("with the constant law (a law refuses it: it gives the thrust)"),
        description: "X_prop, constant at the setting, along body x, positive (ahead: a table \
                      is identified going ahead, and at zero the vehicle lies at rest). Every \
                      run starts from the trim it makes (eom::kinds::vehicle::trim): u and the roll \
                      angle so that u̇ = ṗ = 0, and where that is not a steady motion (W ≠ B, G \
                      and the centre of buoyancy not on one vertical) the whole state but the \
                      position and the heading; a scene without a trim ahead is refused.",
        example: "3.86",
        ..Key::BLANK
    },
    Key {
        path: "propeller.torque",
        families: VEHICLE,
        unit: "N m",
        frame: crate::scene::reference::Frame::Body,
        required: Required::When("with the constant law (0 by default with healey_lienard)"),
        description: "K_prop, the propeller's torque on the hull about body x, constant.",
        example: "-0.543",
        ..Key::BLANK
    },
    Key {
        path: "propeller.rpm",
        families: VEHICLE,
        unit: "rpm",
        required: Required::When("with healey_lienard (the constant law refuses it)"),
        description: "n, the propeller's rate, positive (ahead).",
        example: "1300.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "propeller.advance",
        families: VEHICLE,
        unit: "m/rad",
        required: Required::When("with healey_lienard"),
        description: "a in prop = a·n/u (n in rad/s): the cruise speed per shaft speed, where \
                      thrust meets the resistance (npsauv.m: 0.012).",
        example: "0.012",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "propeller.drag_coefficient",
        families: VEHICLE,
        required: Required::When("with healey_lienard"),
        description: "C_d0: the thrust ½ρL²C_d0(a·n)² (npsauv.m: 0.00385; its resistance \
                      −C_d0 is the table's Xuu).",
        example: "0.00385",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "propeller.thrust_coefficient",
        families: VEHICLE,
        required: Required::When("with healey_lienard"),
        description: "c in C_t = c·L²·prop|prop|/2, the thrust coefficient ε is made of \
                      (npsauv.m: 0.008).",
        example: "0.008",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    RUDDER[0],
    RUDDER[1],
    RUDDER[2],
    STERN_PLANES[0],
    STERN_PLANES[1],
    STERN_PLANES[2],
    // [autopilot]
    Key {
        path: "autopilot.sample_s",
        families: VEHICLE,
        unit: "s",
        required: Required::When("with [autopilot]"),
        description: "The autopilots' sampling period: each computes its fin's command at t = k·sample_s (and at each change of what it holds) and holds it until the next; the run is cut there.",
        example: "0.1",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "autopilot.heading.kp",
        families: VEHICLE,
        required: Required::When("with [autopilot.heading]"),
        description: "The heading autopilot (PID on ψ to the rudder), rad of rudder per rad of heading error. Every gain is positive: the rudder's sense comes from the vehicle's own proved Jacobian at its cruise (∂ṙ/∂δ_r), so a gain means the same on every table.",
        example: "1.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "autopilot.heading.ki",
        families: VEHICLE,
        unit: "1/s",
        default: "0",
        description: "The heading autopilot's integral gain (the rectangle rule at the samples, held while the rudder is at its stop in the error's direction).",
        example: "0.02",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "autopilot.heading.kd",
        families: VEHICLE,
        unit: "s",
        default: "0",
        description: "The heading autopilot's gain on the yaw rate r.",
        example: "1.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "autopilot.depth.kp",
        families: VEHICLE,
        unit: "rad/m",
        required: Required::When("with [autopilot.depth]"),
        description: "The depth autopilot's outer loop: rad of pitch commanded per m of depth error, nose down to go deeper.",
        example: "0.2",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "autopilot.depth.ki",
        families: VEHICLE,
        unit: "rad/(m s)",
        default: "0",
        description: "The outer loop's integral gain.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "autopilot.depth.max_pitch_deg",
        families: VEHICLE,
        unit: "deg",
        required: Required::When("with [autopilot.depth]"),
        description: "The largest pitch the outer loop commands, below 90°.",
        example: "20.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "autopilot.depth.kp_pitch",
        families: VEHICLE,
        required: Required::When("with [autopilot.depth]"),
        description: "The inner loop (PID on θ to the stern planes): rad of planes per rad of pitch error; the planes' sense from the vehicle's ∂q̇/∂δ_s at its cruise.",
        example: "2.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "autopilot.depth.ki_pitch",
        families: VEHICLE,
        unit: "1/s",
        default: "0",
        description: "The inner loop's integral gain.",
        example: "0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "autopilot.depth.kd_pitch",
        families: VEHICLE,
        unit: "s",
        default: "0",
        description: "The inner loop's gain on the pitch rate q.",
        example: "1.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key::shared("integrator.method", VEHICLE, "\"rk4\"", Shown::Set),
    Key::shared("integrator.step", VEHICLE, "0.01", Shown::Set),
    Key::shared("integrator.rtol", VEHICLE, "1e-9", Shown::Commented),
    Key::shared("integrator.atol", VEHICLE, "1e-9", Shown::Commented),
    Key::shared(
        "integrator.max_steps",
        VEHICLE,
        "1_000_000",
        Shown::Commented,
    ),
    Key::shared(
        "integrator.stop_when",
        VEHICLE,
        "\"z > 20\"",
        Shown::Commented,
    ),
    Key {
        path: "manoeuvre[].name",
        families: VEHICLE,
        kind: Kind::Text(Choices::Free),
        default: "its kind",
        description: "The manoeuvre's output folder: letters, digits, _ - ., each name once.",
        example: "\"turn\"",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].kind",
        families: VEHICLE,
        kind: Kind::Text(Choices::These(&[
            "fin_steps",
            "autopilot",
            "turning_circle",
            "zigzag",
        ])),
        required: Required::Yes,
        description: "fin_steps: the fins' commands step at times_s to the angles given, zero \
                      before the first. autopilot: the autopilots hold the heading_deg and \
                      depth_m given from times_s on, the start's before (a fin whose \
                      autopilot holds nothing may take steps); each change is reported with \
                      its overshoot, 2 % settling time and steady error. turning_circle: the \
                      rudder held at rudder_deg from times_s (one of each), the depth held if \
                      depth_m is given; advance and transfer at 90°, tactical diameter at \
                      180°, the steady diameter once the turn has settled. zigzag: the fin of \
                      `plane` to ±fin_deg from times_s, reversed each time the heading (pitch) \
                      passes ±switch_deg; each overshoot read where its rate is zero. Each \
                      manoeuvre starts from its trim at the origin, heading north: the \
                      scene's, with the fins its autopilots work trimmed to hold their heading \
                      and depth from the start, about which they act.",
        example: "\"fin_steps\"",
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].times_s",
        families: VEHICLE,
        kind: Kind::Numbers("the steps' times, strictly increasing"),
        unit: "s",
        required: Required::Yes,
        description: "When the commands step, the first within the run.",
        example: "[2.0, 4.0]",
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].rudder_deg",
        families: VEHICLE,
        kind: Kind::Numbers("the rudder's commands, one per time"),
        unit: "deg",
        required: Required::When("fin_steps: unless stern_planes_deg is given"),
        default: "zero",
        description: "The rudder's command from each time on, within rudder.max_deg.",
        example: "[4.0, -4.0]",
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].stern_planes_deg",
        families: VEHICLE,
        kind: Kind::Numbers("the stern planes' commands, one per time"),
        unit: "deg",
        required: Required::When("fin_steps: unless rudder_deg is given"),
        default: "zero",
        description: "The stern planes' command from each time on, within \
                      stern_planes.max_deg.",
        example: "[0.0, 0.0]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].heading_deg",
        families: VEHICLE,
        kind: Kind::Numbers("headings, one per time"),
        unit: "deg",
        required: Required::When("autopilot: unless depth_m is given"),
        description: "An autopilot manoeuvre: the heading [autopilot.heading] holds from each time on (north 0, east 90).",
        example: "[0.0, 30.0]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].depth_m",
        families: VEHICLE,
        kind: Kind::Numbers("depths, one per time"),
        unit: "m",
        required: Required::When("autopilot: unless heading_deg is given"),
        description: "An autopilot manoeuvre: the depth [autopilot.depth] holds from each time on (down positive, the start at 0).",
        example: "[0.0, 5.0]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].plane",
        families: VEHICLE,
        kind: Kind::Text(Choices::These(&["horizontal", "vertical"])),
        default: "horizontal",
        description: "A zigzag's plane: `horizontal` (the rudder, switched on the heading change) or `vertical` (the stern planes, switched on the pitch).",
        example: "\"vertical\"",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].fin_deg",
        families: VEHICLE,
        unit: "deg",
        required: Required::When("for a zigzag"),
        description: "A zigzag's fin angle, below 90° and within its fin's max_deg: the fin goes to it at the execute, and to its opposite at each switch.",
        example: "10.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].switch_deg",
        families: VEHICLE,
        unit: "deg",
        required: Required::When("for a zigzag"),
        description: "A zigzag's switch angle, below 90°: of the heading from the execute's, or of the pitch from the trim's.",
        example: "10.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].duration_s",
        families: VEHICLE,
        unit: "s",
        required: Required::Yes,
        description: "The end of the run.",
        example: "6.0",
        ..Key::BLANK
    },
    Key {
        path: "output.every",
        families: VEHICLE,
        unit: "s",
        required: Required::When("for an adaptive method"),
        default: "the step",
        description: "Trajectory rows at exactly t = k·every, and a row at each change of the \
                      commands.",
        example: "0.1",
        ..Key::BLANK
    },
    // [linear]
    Key {
        path: "linear.at.*",
        families: VEHICLE,
        kind: Kind::Table("state entries and inputs by name, and values"),
        description: "The operating point of `eom linear`, where it differs from the trim: \
                      `u`, `v`, `w`, `p`, `q`, `r` (SI), `phi`, `theta`, `psi` (rad) and the \
                      fins' angles `dr`, `ds` (or `rudder`, `stern_planes`, rad). The vehicle is \
                      linearised in Euler angles, the Euler-angle twin of its table.",
        example: "theta = 0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "linear.trim",
        families: VEHICLE,
        kind: Kind::Names("state entries or inputs"),
        description: "Free variables of `eom linear`, solved for by Newton's method on the \
                      reduced state so that the point is an equilibrium (a clear error when it \
                      does not converge): `[\"u\", \"phi\"]` is the cruise the propeller holds, \
                      `[\"theta\", \"stern_planes\"]` a vehicle's pitch and planes at a depth \
                      rate of zero.",
        example: "[\"u\", \"phi\"]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "linear.outputs",
        families: VEHICLE,
        kind: Kind::Names("state entries"),
        description: "Outputs of the linear model `eom linear` writes (y = C x + D u in \
                      linear.json and linear.mat): state entries of the Euler-angle twin by \
                      name, each in the reduced state at the point (not x, y, z or psi at a \
                      cruise, which are set aside); C picks them, D is zero. By default every \
                      entry of the reduced state (C the identity).",
        example: "[\"r\", \"theta\"]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key::shared(
        "sweep.*",
        VEHICLE,
        "\"hydrodynamics.coefficients.Nuudr\" = [-4.92, -6.15, -7.38]",
        Shown::Commented,
    ),
    // [uncertainty]
    Key::shared("uncertainty.cases", VEHICLE, "1000", Shown::Commented),
    Key::shared("uncertainty.seed", VEHICLE, "1", Shown::Commented),
    Key::shared(
        "uncertainty.vary.*",
        VEHICLE,
        "\"hydrodynamics.coefficients.N*\" = { distribution = \"uniform\", relative = 0.2 }",
        Shown::Commented,
    ),
];
