//! The keys every scene takes, whatever its kind: its title, its method and the method's
//! settings, its sweep and its Monte Carlo. Each is defined here once (its type, unit, default, whether it is
//! required and what it means); a family's list of keys names it where its templates write
//! it, with the example its template sets ([`Key::shared`]), so that the reference page
//! writes it once and every template writes it in its place.

use super::{Choices, Key, Kind, Required};

/// The keys every scene takes. `families`, `example` and `shown` are each family's own
/// ([`Key::shared`]).
pub(super) static KEYS: &[Key] = &[
    Key {
        path: "title",
        kind: Kind::Text(Choices::Free),
        required: Required::Yes,
        description: "What the scene is: the title of the summary and the plots.",
        ..Key::BLANK
    },
    Key {
        path: "integrator.method",
        kind: Kind::Text(Choices::Methods),
        required: Required::Yes,
        description: "How to integrate. Fixed step: euler, symplectic-euler, rk4, and \
                      lie-midpoint for a catalog spatial body with quaternion kinematics under \
                      no load or uniform gravity alone (the rotation by the geometric \
                      integrator, the translation exactly; no other scene takes it). Adaptive, \
                      rows placed by dense output: dopri5, dop853. A run is cut at each change \
                      of its schedule (a load table's times, a change of a manoeuvre's \
                      commands) and at each of its events (a manoeuvre's heading passing 90°, \
                      180° or ±ψ_a, its yaw rate passing zero, a steering gear reaching or \
                      leaving its rate limit; a stop condition), located to adjacent \
                      floating-point numbers of t on the method's solution: the dense output \
                      of dopri5 and dop853, the step taken again for the fixed-step methods.",
        ..Key::BLANK
    },
    Key {
        path: "integrator.step",
        unit: "s",
        required: Required::When("for a fixed-step method"),
        description: "Fixed-step methods only: the largest step. Each interval between rows \
                      is integrated in equal steps of at most this, so that rows land on their \
                      times. A run's figures are measured again at half the step taken, and \
                      summary.json says how far each moves (`half_step_difference`; a \
                      manoeuvre's largest, `refined_difference`, where its figures are many). \
                      A catalog body's run stops where h·|ω| passes the method's stability \
                      limit on the imaginary axis (rk4 2√2 ≈ 2.83, symplectic Euler 2 on the \
                      pendulum; |ω| the body's rate, |r| planar, √(Mgh/I₀) for the pendulum). \
                      Explicit Euler is unstable there for every step, and so is symplectic \
                      Euler on a body's rates, which it kicks together: they only warn, as any \
                      fixed step does past the h·|ω| at which one turn errs by 10 % (0.0318 \
                      Euler, 1.18 rk4). The bounds and their derivations: src/kinds/body/guard.rs.",
        ..Key::BLANK
    },
    Key {
        path: "integrator.rtol",
        unit: "-",
        default: "1e-9",
        description: "Adaptive methods only: the relative tolerance, at least ten rounding \
                      units of f64 (1.1e-15), below which a method takes more steps for no \
                      accuracy. A run's figures are measured again with rtol and atol a \
                      hundred times tighter, and summary.json says how far each moves \
                      (`tolerance_difference`; a manoeuvre's largest, `refined_difference`, \
                      where its figures are many).",
        ..Key::BLANK
    },
    Key {
        path: "integrator.atol",
        default: "1e-9",
        description: "Adaptive methods only: the absolute tolerance, in each state entry's \
                      own unit.",
        ..Key::BLANK
    },
    Key {
        path: "integrator.max_steps",
        kind: Kind::Integer,
        default: "1_000_000",
        description: "The most steps, accepted and rejected, a run may take: a catalog \
                      scene's one run, or each manoeuvre.",
        ..Key::BLANK
    },
    Key {
        path: "integrator.stop_when",
        kind: Kind::Text(Choices::Free),
        default: "none: the run ends at its end",
        description: "A condition that ends a run where it first holds: t or a column of \
                      its trajectory.csv by its name before the unit (a state entry; a ship's \
                      and a vehicle's commands and a ship's distance too, not the energies), \
                      then <, >, <= or >=, then a number (`z > 10`: the ground). A catalog \
                      scene's run is one; a \
                      ship's or a vehicle's manoeuvre (each side) is each one, t its own time \
                      from 0, a condition that holds where one starts is refused. The crossing \
                      is found on the step to adjacent doubles, with the last row there; \
                      summary.json says stop_when and stopped_at (each manoeuvre's, each \
                      side's). A manoeuvre's figure it had not read by then is not given, one \
                      read at the end (a steady turn) neither, and a note says why.",
        ..Key::BLANK
    },
    Key {
        path: "sweep.*",
        kind: Kind::Table("key paths and values"),
        description: "Values to vary, one run of the scene per combination, in parallel, each \
                      case into case-NNNN/ with one line per case in sweep.csv (the swept \
                      values and the run's figures: each manoeuvre's, each verdict's value and \
                      whether it passed): a key's path in quotes (an entry of the manoeuvre \
                      array by its index, `manoeuvre[0].rudder_deg`) and a list of values, or \
                      { from, to, count } evenly spaced. At most 100 000 cases a run, numbered \
                      in a fixed order (keys sorted, the last varying fastest); `eom run \
                      --shard K/N` runs the cases k ≡ K (mod N) and `eom sweep-merge` joins \
                      the shards' tables.",
        ..Key::BLANK
    },
    Key {
        path: "uncertainty.cases",
        kind: Kind::Integer,
        required: Required::When("in a Monte Carlo"),
        description: "An [uncertainty] table makes the scene a Monte Carlo: this many cases, \
                      each the scene with the values of [uncertainty.vary] drawn afresh, run \
                      once in parallel (its rows dropped, not run again refined) into one line \
                      of uncertainty.csv (the values, each run's figures, each verdict, every \
                      digit); uncertainty.json gives each figure's mean, standard deviation and \
                      5th, 50th and 95th percentiles and each verdict's pass rate with its 95 % \
                      Wilson interval, distributions.svg and pass_rates.svg draw them. At most \
                      10⁶ cases a run; `eom run --shard K/N` runs the cases k ≡ K (mod N) and \
                      `eom sweep-merge` joins the shards into what one run writes, the same \
                      numbers. A scene has a [sweep] or an [uncertainty], not both.",
        ..Key::BLANK
    },
    Key {
        path: "uncertainty.seed",
        kind: Kind::Integer,
        required: Required::When("in a Monte Carlo"),
        description: "The seed of every case's stream: case k draws its values from ChaCha8 \
                      seeded by it on stream k, the varied numbers in the order of their paths, \
                      so that a case is the same in any shard, on any number of threads.",
        ..Key::BLANK
    },
    Key {
        path: "uncertainty.vary.*",
        kind: Kind::Table("key paths and laws"),
        required: Required::When("in a Monte Carlo"),
        description: "The numbers to vary: a key path in quotes (an entry of an array of \
                      tables by its index, `manoeuvre[0].rudder_deg`), whose last part may be a \
                      pattern in which * stands for any run of characters \
                      (`hydrodynamics.coefficients.*`: every number of that table), and its \
                      law, each number varied on its own from the value the scene writes: \
                      { distribution = \"normal\", sigma = σ } (in the key's unit) or \
                      sigma_relative (a fraction of the scene's value, so a zero stays zero), \
                      with truncate = t to draw again beyond ±tσ (t ≥ 0.1); or \
                      { distribution = \"uniform\", low, high } or relative (± a fraction of \
                      the scene's value). A path that names no number the scene writes, or a \
                      number two paths name, is refused. A case whose values the scene refuses \
                      (a mass below zero) fails alone and is counted apart.",
        ..Key::BLANK
    },
];

/// The definition of the shared key at `path`, if there is one.
pub(super) fn definition(path: &str) -> Option<&'static Key> {
    KEYS.iter().find(|key| key.path == path)
}
