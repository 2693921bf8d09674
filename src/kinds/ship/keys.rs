//! The keys of a ship scene (`eom::kinds::ship::scene::ShipSceneFile`), in the order a template
//! writes them. The template's ship is the Esso Osaka of `scenes/esso_osaka.toml` (its
//! sources and estimates are said there), in the prime system, with the dimensional keys
//! shown commented out beside their prime counterparts.

pub mod environment;

use crate::scene::reference::{Choices, Frame, Key, Kind, Required, SceneFamily, Shown};

pub(crate) const SHIP: &[SceneFamily] = &[SceneFamily::Kind("ship")];

/// The yaw inertia: one of four keys, by the table's units and the point it is taken about.
const ONE_YAW_INERTIA: Required = Required::When(
    "as one of izz, izz_midship (dimensional), izz_prime, izz_midship_prime (prime)",
);

/// The keys of a ship scene up to `[environment]`: the ship, its table, its rudder and
/// propeller.
pub const KEYS: &[Key] = &[
    Key::shared(
        "title",
        SHIP,
        "\"A ship from eom new: the Esso Osaka of scenes/esso_osaka.toml\"",
        Shown::Set,
    ),
    Key {
        path: "model.family",
        families: SHIP,
        kind: Kind::Text(Choices::These(&["planar-midship"])),
        required: Required::Yes,
        description: "A ship runs 4.46 at midship; the [hydrodynamics] table with this \
                      family is what makes a scene a ship scene.",
        example: "\"planar-midship\"",
        ..Key::BLANK
    },
    // [body]: in the table's units, one key of each quantity.
    Key {
        path: "body.length",
        families: SHIP,
        unit: "m",
        required: Required::Yes,
        description: "L, the ship's length: the prime system's unit of length, and the IMO \
                      criteria's (always in metres).",
        example: "325.0",
        ..Key::BLANK
    },
    Key {
        path: "body.mass",
        families: SHIP,
        unit: "kg",
        required: Required::When("in a dimensional table"),
        description: "M, the ship's mass.",
        example: "3.184e8",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "body.mass_prime",
        families: SHIP,
        unit: "-",
        required: Required::When("in a prime table"),
        description: "m′ = M/(½ρL³).",
        example: "0.0181",
        ..Key::BLANK
    },
    Key {
        path: "body.izz",
        families: SHIP,
        unit: "kg m²",
        required: ONE_YAW_INERTIA,
        description: "The yaw inertia I_zz about G, as 4.46 writes it (dimensional).",
        example: "2.066e12",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "body.izz_midship",
        families: SHIP,
        unit: "kg m²",
        required: ONE_YAW_INERTIA,
        description: "The yaw inertia I_O about midship (dimensional), as many tables' mass \
                      matrices hold it; 4.46 takes I_zz = I_O − M x_G² (4.45), which must be \
                      positive.",
        example: "2.100e12",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "body.izz_prime",
        families: SHIP,
        unit: "-",
        required: ONE_YAW_INERTIA,
        description: "I_zz′, the yaw inertia about G over ½ρL⁵ (prime).",
        example: "0.0011118",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "body.izz_midship_prime",
        families: SHIP,
        unit: "-",
        required: ONE_YAW_INERTIA,
        description: "I_O′, the yaw inertia about midship over ½ρL⁵ (prime).",
        example: "0.00113",
        ..Key::BLANK
    },
    Key {
        path: "body.x_g",
        families: SHIP,
        unit: "m",
        frame: Frame::Body,
        required: Required::When("in a dimensional table"),
        description: "x_G, how far G lies ahead of midship.",
        example: "10.30",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "body.x_g_prime",
        families: SHIP,
        unit: "-",
        frame: Frame::Body,
        required: Required::When("in a prime table"),
        description: "x_G′ = x_G/L.",
        example: "0.0316923",
        ..Key::BLANK
    },
    // [hydrodynamics]
    Key {
        path: "hydrodynamics.model",
        families: SHIP,
        kind: Kind::Text(Choices::These(&["polynomial", "mmg"])),
        default: "\"polynomial\"",
        description: "`polynomial`: one table of the whole ship's forces (Abkowitz's; the \
                      Mariner's), in `units`, named term by term. `mmg`: the MMG standard \
                      method (Yasukawa & Yoshimura 2015; eom::kinds::ship::mmg): the body in SI \
                      (body.mass, body.izz or izz_midship, body.x_g), the hull's, propeller's \
                      and rudder's coefficients by the names of data/kvlcc2_mmg.json, the \
                      particulars B, d, D_P, H_R, A_R, density; no units, rigid_body_terms or \
                      [propulsion]. The propeller rate is held at the rate that balances the \
                      approach at design_speed, solved; δ > 0 turns the ship to starboard.",
        example: "\"polynomial\"",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.units",
        families: SHIP,
        kind: Kind::Text(Choices::These(&["prime", "dimensional"])),
        required: Required::When("in a polynomial table"),
        description: "The units of every number of the table and of the body. `dimensional`: \
                      SI (N, N m, kg, m, s, rad), a term Y_vvr adds Y_vvr·v²r newtons. \
                      `prime`: forces over ½ρU²L², moments over ½ρU²L³, mass over ½ρL³, I_zz \
                      over ½ρL⁵, lengths over L, u and v over U, r over U/L, the surge variable \
                      the perturbation (u − U₀)/U, with U = √(u² + v²) the speed at the \
                      instant: a term adds ½ρL²U²·Y′_vvr(v/U)²(rL/U).",
        example: "\"prime\"",
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.rigid_body_terms",
        families: SHIP,
        kind: Kind::Text(Choices::These(&["folded", "separate"])),
        required: Required::When("in a polynomial table"),
        description: "`separate`: the table is hydrodynamic only, and 4.46 adds its rigid-body \
                      terms (M v r, M x_G r², M u r, M x_G u r). `folded`: the table holds them, \
                      as many published ones do (the Mariner's X_vr = m′, Y_r − m′, …); eom \
                      takes m′ and m′x_G′ back out of X_vr, X_rr, Y_r, Y_ur, N_r, N_ur and lists \
                      each conversion in summary.json.",
        example: "\"separate\"",
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.density",
        families: SHIP,
        unit: "kg/m³",
        required: Required::When("in a prime or an MMG table (a dimensional one refuses it)"),
        description: "ρ, the water's density.",
        example: "1025.0",
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.design_speed",
        families: SHIP,
        unit: "m/s",
        required: Required::Yes,
        description: "U₀: every manoeuvre starts straight ahead at it; the prime system's \
                      reference of the surge perturbation.",
        example: "4.1156",
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.propeller_rate_rps",
        families: SHIP,
        unit: "rev/s",
        default: "the rate that balances the approach at design_speed, solved",
        description: "An MMG ship's propeller rate, held in every run. By default eom solves \
                      the rate at which the propeller's thrust balances the hull's resistance \
                      at design_speed (SIMMAN's setup), so the approach is steady; a rate given \
                      here (a model test's measured rate, a public code's) is held instead, \
                      and summary.json model.mmg gives the surge force it leaves at the \
                      approach, which the run's first seconds then feel.",
        example: "10.33",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.coefficients.*",
        families: SHIP,
        kind: Kind::Table("coefficient names and numbers"),
        unit: "the table's units",
        required: Required::Yes,
        description: "The terms to model, and only those: eom derives 4.46 with exactly these \
                      and proves it before the run. A name is the load (X, Y or N), then one \
                      letter per power of u, v, r and δ (d), in any order: Yvvr multiplies v²r \
                      in Y, Xrv and Xvr are one term, Nd multiplies δ in N. A 0 marks a bias \
                      (Y0; Y0u is the same term as Yu); an underscore may follow the load \
                      (Y_vvr). The added mass is Xudot, Yvdot, Yrdot, Nvdot, Nrdot. Each \
                      number is kept as written. In an MMG table (model = \"mmg\") the names \
                      are the method's, as data/kvlcc2_mmg.json writes them: m_x_p, m_y_p, \
                      J_z_p (on ½ρL²d, ½ρL⁴d), R_0_p and the hull's X_vv_p, X_vr_p, X_rr_p, \
                      X_vvvv_p, Y_ and N_ v, r, vvv, vvr, vrr, rrr _p (on ½ρLdU², ½ρL²dU², in \
                      v′ = v/U, r′ = rL/U), the propeller's t_P, w_P0, x_P_p, k_0, k_1, k_2, \
                      C_1, C_2_plus, C_2_minus, the rudder's t_R, a_H, x_H_p, x_R_p, \
                      gamma_R_plus, gamma_R_minus, l_R_p, epsilon, kappa and f_alpha (optional: \
                      Fujii's 6.13Λ/(Λ + 2.25) at Λ = H_R²/A_R without it); every one but \
                      f_alpha required, any other name refused.",
        example: "Xudot = -0.0007\nYvdot = -0.0171\nNrdot = -0.00109\nXu = -0.00113\n\
                  Xvv = -0.006\nXrr = 0.00515\nXvr = 0.0085\nYv = -0.0261\nYr = 0.00365\n\
                  Yvrr = -0.045\nYd = 0.00717\nNv = -0.0105\nNr = -0.0048\nNvrr = 0.00611\n\
                  Nd = -0.00399",
        ..Key::BLANK
    },
    Key {
        path: "hydrodynamics.particulars.*",
        families: SHIP,
        kind: Kind::Table("particular names and numbers"),
        unit: "m, m²",
        required: Required::When("in an MMG table"),
        description: "An MMG ship's particulars beside the body's length and x_G: B (breadth), \
                      d (draft), D_P (the propeller's diameter), H_R (the rudder's span), A_R \
                      (the rudder's area, m²); each positive, every one required.",
        example: "B = 1.27\nd = 0.46\nD_P = 0.216\nH_R = 0.345\nA_R = 0.0539",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    // [rudder]: every key optional.
    Key {
        path: "rudder.max_deg",
        families: SHIP,
        unit: "deg",
        default: "no limit",
        description: "δ_max, where the rudder saturates.",
        example: "35.0",
        ..Key::BLANK
    },
    Key {
        path: "rudder.max_rate_deg_s",
        families: SHIP,
        unit: "deg/s",
        default: "no limit",
        description: "δ̇_max, the steering gear's rate limit; it acts on the lag's rate, so it \
                      needs rudder.time_constant_s.",
        example: "2.32",
        ..Key::BLANK
    },
    Key {
        path: "rudder.time_constant_s",
        families: SHIP,
        unit: "s",
        default: "no lag: the rudder is at its command",
        description: "The steering gear's first-order lag.",
        example: "1.0",
        ..Key::BLANK
    },
    // [propulsion]
    Key {
        path: "propulsion.diameter",
        families: SHIP,
        unit: "m",
        required: Required::When("with [propulsion]"),
        description: "d, the propeller's diameter. [propulsion] is optional (prime tables only): with it the propeller rate is the model's second input, the thrust law and the resistance are in X, the rudder's terms are on its inflow speed c and the bias terms on the propeller's induced velocity (eom::kinds::ship::propulsion), and a crash_stop can be run.",
        example: "9.1",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "propulsion.rudder_area",
        families: SHIP,
        unit: "m²",
        required: Required::When("with [propulsion]"),
        description: "A_R, the rudder's area; the share A_p/A_R of it (A_p = π d²/4) is in the slipstream.",
        example: "119.817",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "propulsion.wake_fraction",
        families: SHIP,
        unit: "-",
        required: Required::When("with [propulsion]"),
        description: "w: the flow reaches the propeller at (1 − w) u.",
        example: "0.2",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "propulsion.thrust_coefficient",
        families: SHIP,
        unit: "-",
        required: Required::When("with [propulsion]"),
        description: "K_T of momentum theory's induced velocity far behind the propeller, u_A = −(1 − w)u + √((1 − w)²u² + (8/π) K_T (n d)²), ahead (n > 0); none astern.",
        example: "0.59",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "propulsion.slipstream_factor",
        families: SHIP,
        unit: "-",
        required: Required::When("with [propulsion]"),
        description: "k: the share of u_A that reaches the rudder, c² = (A_p/A_R)((1 − w)u + k u_A)² + (1 − A_p/A_R)((1 − w)u)².",
        example: "0.95",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "propulsion.rudder_position_prime",
        families: SHIP,
        unit: "-",
        required: Required::When("with [propulsion]"),
        description: "x_R/L, the rudder's position ahead of midship (negative aft): the effective rudder angle is e = δ − (v + x_R r)/c.",
        example: "-0.5",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "propulsion.thrust",
        families: SHIP,
        kind: Kind::Numbers("three numbers"),
        unit: "-",
        required: Required::When("with [propulsion]"),
        description: "T′_uu, T′_un, T′_nn of the thrust law ½ρL²(T′_uu u² + T′_un L n u + T′_nn L² n|n|), n in rev/s; the rate at the approach, n₀, is the one at which it balances the resistance at U₀.",
        example: "[-0.962e-5, -0.446e-5, 0.0309e-5]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "propulsion.resistance",
        families: SHIP,
        unit: "-",
        required: Required::When("with [propulsion]"),
        description: "C_R, the resistance ½ρ S C_R u² on the wetted surface S, against the thrust.",
        example: "0.00226",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "propulsion.wetted_surface",
        families: SHIP,
        unit: "m²",
        required: Required::When("with [propulsion]"),
        description: "S, the wetted surface the resistance is on.",
        example: "26319.8",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "propulsion.max_rate_rps_s",
        families: SHIP,
        unit: "rev/s²",
        required: Required::When("with [propulsion]"),
        description: "The engine's rate limit: a change of the propeller rate's command (a crash stop's) is reached at this rate.",
        example: "0.0167",
        shown: Shown::Commented,
        ..Key::BLANK
    },
];

/// The keys after `[environment]` and `[windage]` ([`environment::KEYS`]): the step, the
/// manoeuvres, the output, the linear model.
pub const RUN_KEYS: &[Key] = &[
    // [integrator]
    Key::shared("integrator.method", SHIP, "\"rk4\"", Shown::Set),
    Key::shared("integrator.step", SHIP, "0.2", Shown::Set),
    Key::shared("integrator.rtol", SHIP, "1e-9", Shown::Commented),
    Key::shared("integrator.atol", SHIP, "1e-9", Shown::Commented),
    Key::shared("integrator.max_steps", SHIP, "1_000_000", Shown::Commented),
    Key::shared("integrator.stop_when", SHIP, "\"u < 1\"", Shown::Commented),
    // [[manoeuvre]]: at least one; each kind reads its own keys and refuses the others.
    Key {
        path: "manoeuvre[].name",
        families: SHIP,
        kind: Kind::Text(Choices::Free),
        default: "the kind and angles: turning_circle_35, zigzag_10_10",
        description: "The manoeuvre's output folder: letters, digits, _ - . (not imo), each \
                      name once.",
        example: "\"turn\"",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].kind",
        families: SHIP,
        kind: Kind::Text(Choices::These(&[
            "turning_circle",
            "zigzag",
            "pull_out",
            "rudder_series",
            "spiral",
            "reverse_spiral",
            "crash_stop",
        ])),
        required: Required::Yes,
        description: "Which manoeuvre. Each starts straight ahead at U₀, midship at the \
                      origin, heading north, rudder amidships. spiral: Dieudonné's direct \
                      spiral; reverse_spiral: Bech's reverse spiral (the steady yaw rate \
                      against the rudder angle, and its loop; see eom::kinds::ship::spiral); \
                      crash_stop (with [propulsion]): full ahead to full astern, the rudder \
                      amidships, until the ship stops (u = 0).",
        example: "\"turning_circle\"",
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].rudder_deg",
        families: SHIP,
        unit: "deg",
        required: Required::When("for turning_circle, zigzag and pull_out"),
        description: "The rudder angle put over at the execute (a zig-zag's δ_a), not zero. A \
                      turning circle or zig-zag puts its magnitude to the side (or sides) of \
                      `side`; a pull-out uses it as signed (positive δ turns the tables here \
                      to port).",
        example: "35.0",
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].side",
        families: SHIP,
        kind: Kind::Text(Choices::These(&["both", "port", "starboard"])),
        default: "both",
        description: "turning_circle and zigzag: the side the rudder turns the ship to \
                      (a zig-zag's first turn). both: one run to each, written into \
                      NAME/port/ and NAME/starboard/, the summary's figures those of the worse \
                      side with each side's under `sides`, each IMO criterion judged on both \
                      and its verdict the worse. Which sign of δ turns to port is read from \
                      the table's linear model (the yaw acceleration a rudder angle gives).",
        example: "\"both\"",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].heading_deg",
        families: SHIP,
        unit: "deg",
        required: Required::When("for zigzag"),
        description: "ψ_a, the heading change at which a zig-zag reverses its rudder.",
        example: "10.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].execute_s",
        families: SHIP,
        unit: "s",
        default: "0",
        description: "When the rudder is put over; the figures are measured from here.",
        example: "0.0",
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].release_s",
        families: SHIP,
        unit: "s",
        required: Required::When("for pull_out"),
        description: "When a pull-out puts its rudder back to zero: after the execute, before \
                      the end.",
        example: "30.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].duration_s",
        families: SHIP,
        unit: "s",
        required: Required::When("except for spiral and reverse_spiral"),
        default: "a spiral's: the longest it may take, every setpoint held max_hold_s",
        description: "The end of the run, after the execute. A spiral ends once every \
                      setpoint is measured. A turn's steady radius and speed are read once the \
                      heading has turned 540° and U and r have settled: for a 325 m tanker at \
                      8 knots, after some two hours (the template's 8000 s).",
        example: "8000.0",
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].times_s",
        families: SHIP,
        kind: Kind::Numbers("the command's times, strictly increasing"),
        unit: "s",
        required: Required::When("for rudder_series"),
        description: "The times of a rudder series' command, piecewise linear between them \
                      and constant before the first and after the last.",
        example: "[0.0, 10.0, 20.0]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].series_deg",
        families: SHIP,
        kind: Kind::Numbers("the command's angles, one per time"),
        unit: "deg",
        required: Required::When("for rudder_series"),
        description: "The command's angle at each of times_s.",
        example: "[0.0, 10.0, -10.0]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].rudders_deg",
        families: SHIP,
        kind: Kind::Numbers("the first pass's angles, strictly monotonic"),
        unit: "deg",
        required: Required::When("for spiral, unless from_deg, to_deg and step_deg give them"),
        description: "The direct spiral's rudder angles, from one side through zero to the \
                      other; the run holds each until r settles, then comes back through \
                      them in reverse.",
        example: "[10.0, 5.0, 2.0, 1.0, 0.0, -1.0, -2.0, -5.0, -10.0]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].from_deg",
        families: SHIP,
        unit: "deg",
        required: Required::When("for spiral, with to_deg and step_deg, instead of rudders_deg"),
        description: "The direct spiral's first angle: the first pass runs from it to to_deg \
                      every step_deg. Give either rudders_deg or these three, not both.",
        example: "10.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].to_deg",
        families: SHIP,
        unit: "deg",
        required: Required::When("with from_deg"),
        description: "The direct spiral's last angle of the first pass; from_deg to to_deg \
                      must be a whole number of steps.",
        example: "-10.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].step_deg",
        families: SHIP,
        unit: "deg",
        required: Required::When("with from_deg"),
        description: "The spacing of the direct spiral's angles from from_deg to to_deg, \
                      positive; each angle is from_deg plus a whole number of steps.",
        example: "1.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].astern_rps",
        families: SHIP,
        unit: "rev/s",
        required: Required::When("for crash_stop"),
        description: "crash_stop: the full-astern propeller rate commanded at the execute (negative), reached from the approach's n₀ at propulsion.max_rate_rps_s.",
        example: "-0.64",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].yaw_rates_deg_s",
        families: SHIP,
        kind: Kind::Numbers("the commanded yaw rates, in the order run"),
        unit: "deg/s",
        required: Required::When("for reverse_spiral"),
        description: "The reverse spiral's commanded yaw rates, each held by a controller on \
                      the rudder until r and the mean rudder settle.",
        example: "[0.15, 0.1, 0.05, 0.0, -0.05, -0.1, -0.15]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].settle_window_s",
        families: SHIP,
        unit: "s",
        default: "100",
        description: "spiral, reverse_spiral: r is checked at the end of each window of this \
                      length from the setpoint's start; it has settled when it varied by at \
                      most settle_tolerance_deg_s over the window.",
        example: "100.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].settle_tolerance_deg_s",
        families: SHIP,
        unit: "deg/s",
        default: "0.001",
        description: "spiral, reverse_spiral: the largest variation of r (max − min) over the \
                      window for a settled setpoint (and, for the reverse spiral, the largest \
                      distance of the mean r from the commanded one). For an approach as one \
                      exponential of time constant T, a settled r is within ε = \
                      tolerance/(e^(W/T) − 1) of the steady one; with T = |T₁| of the linear \
                      model, a direct spiral's passes closer than 2ε are not read as a loop.",
        example: "0.001",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].settle_speed_m_s",
        families: SHIP,
        unit: "m/s",
        default: "0.001",
        description: "spiral, reverse_spiral: the largest variation of the speed u (max − \
                      min) over the window for a settled setpoint. The speed converges slowest \
                      and r and the rudder follow it: an r that overshoots and turns back \
                      stops moving for a window while the turn is still far from steady.",
        example: "0.001",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].settle_rudder_deg",
        families: SHIP,
        unit: "deg",
        default: "0.01",
        description: "reverse_spiral: the largest change of the mean rudder angle from one \
                      window to the next for a settled setpoint.",
        example: "0.01",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].max_hold_s",
        families: SHIP,
        unit: "s",
        default: "2000",
        description: "spiral, reverse_spiral: the longest a setpoint is held; one not settled \
                      by then is taken as it stands, marked settled: false, with a note.",
        example: "2000.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "manoeuvre[].controller_time_s",
        families: SHIP,
        unit: "s",
        default: "20",
        description: "reverse_spiral: τ of the controller δ_c = δ_i + g (r − r_c), g = \
                      −1/(b_r τ) with b_r the yaw acceleration per radian of rudder about \
                      the straight course; δ_i moves at each check by g (r̄ − r_c).",
        example: "20.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    // [output]
    Key {
        path: "output.every",
        families: SHIP,
        unit: "s",
        required: Required::When("for an adaptive method"),
        default: "the step",
        description: "Trajectory rows at exactly t = k·every, and a row at each event and \
                      each change of the rudder's schedule.",
        example: "1.0",
        ..Key::BLANK
    },
    // [linear]
    Key {
        path: "linear.at.*",
        families: SHIP,
        kind: Kind::Table("state entries and inputs by name, and values"),
        description: "The operating point of `eom linear`, where it differs from the approach \
                      (straight ahead at U₀, the rudder amidships): `u`, `v`, `r` (SI), `psi` \
                      and the rudder angle `delta` (or `rudder`) in radians.",
        example: "delta = 0.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "linear.trim",
        families: SHIP,
        kind: Kind::Names("state entries or inputs"),
        description: "Free variables of `eom linear`, solved for by Newton's method on (u, v, r) \
                      so that the point is an equilibrium: `[\"rudder\", \"v\", \"u\"]` finds \
                      the rudder angle, the drift and the speed that keep a ship with bias \
                      terms on a straight course (a clear error when it does not converge).",
        example: "[\"rudder\", \"v\", \"u\"]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "linear.outputs",
        families: SHIP,
        kind: Kind::Names("state entries"),
        description: "Outputs of the linear model `eom linear` writes (y = C x + D u in \
                      linear.json and linear.mat): entries of (u, v, r) by name; C picks \
                      them, D is zero. By default all three (C the identity).",
        example: "[\"v\", \"r\"]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    // [sweep]
    Key::shared(
        "sweep.*",
        SHIP,
        "\"manoeuvre[0].rudder_deg\" = [5.0, 10.0, 15.0, 20.0, 25.0, 30.0, 35.0]",
        Shown::Commented,
    ),
    // [uncertainty]
    Key::shared("uncertainty.cases", SHIP, "1000", Shown::Commented),
    Key::shared("uncertainty.seed", SHIP, "1", Shown::Commented),
    Key::shared(
        "uncertainty.vary.*",
        SHIP,
        "\"hydrodynamics.coefficients.*\" = { distribution = \"normal\", sigma_relative = 0.1, truncate = 3.0 }",
        Shown::Commented,
    ),
];

/// What docs/scenes.md says after a ship's keys: the conventions of its table.
pub const NOTES: &str = "### The hydrodynamic table\n\n\
- **Term names.** A coefficient's name is its load, X, Y or N, then one letter per power of u, \
v, r and δ (`d`), in any order: `Yvvr` is the coefficient of v²r in Y, `Xrv` and `Xvr` name one \
term, `Nuud` multiplies u²δ in N. `0` marks a bias (`Y0`, `N0`; `Y0u` is the same term as \
`Yu`), and an underscore may follow the load (`Y_vvr`). The added mass is `Xudot`, `Yvdot`, \
`Yrdot`, `Nvdot`, `Nrdot`, on the left of 4.46. Only the terms listed are modelled: a table of \
eight terms emits eight products. With `[propulsion]`, `e` is a letter too, the effective rudder \
angle (`Xee`, `Yeee`), the terms in δ or e alone are on the rudder's inflow speed c, and a bias \
is the propeller's, on its induced velocity (docs/ships.md, The Esso Osaka as published).\n\
- **Prime system or SI.** `units = \"prime\"` reads every number in the prime system (forces \
over ½ρU²L², moments over ½ρU²L³, mass over ½ρL³, I_zz over ½ρL⁵, lengths over L, u and v \
over U, r over U/L, the surge variable (u − U₀)/U) and needs `density`; the body's keys end \
in `_prime` (`mass_prime`, `x_g_prime`). `units = \"dimensional\"` reads SI and refuses \
`density`; the body's keys are `mass`, `x_g`. `length` is in metres either way.\n\
- **Yaw inertia.** Give exactly one of four: about G (`izz`, `izz_prime`), as 4.46 writes it, \
or about midship (`izz_midship`, `izz_midship_prime`), as many tables' mass matrices hold it, \
taken to G by I_zz = I_O − M x_G² (4.45). Each is read as written.\n\
- **Folded tables.** `rigid_body_terms = \"folded\"` for a table that holds 4.46's \
rigid-body terms in its coefficients; `eom` takes them out and lists each conversion in \
`summary.json`.\n";
