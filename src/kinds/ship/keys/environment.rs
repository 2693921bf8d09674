//! The keys of a ship's surroundings: `[environment]` (a uniform current, a wind steady or
//! gusting) and `[windage]` (the ship above water: its areas and wind coefficients).

use super::SHIP;
use crate::scene::reference::{Choices, Key, Kind, Required, Shown};

/// The keys of `[environment]` and `[windage]`, after the propeller's.
pub const KEYS: &[Key] = &[
    Key {
        path: "environment.current_m_s",
        families: SHIP,
        unit: "m/s",
        default: "no current",
        description: "A uniform current's speed, constant in space and time, with \
                      current_toward_deg. The ship's u and v (and U, the speeds of the figures \
                      and the trajectory) are then through the water, what the hydrodynamic \
                      forces see, and its track X, Y over ground, carried by the current: the \
                      advance, transfer and tactical diameter are over ground, and a turning \
                      circle drifts (its figures drift_m_per_turn, drift_toward_deg and \
                      turn_period_s, from the turns at 360° and 720° of heading change).",
        example: "0.5",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "environment.current_toward_deg",
        families: SHIP,
        unit: "deg",
        required: Required::When("with environment.current_m_s"),
        description: "The direction the current flows toward (its set, as currents are \
                      given), clockwise from north (X): 90 flows east.",
        example: "90.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "environment.wind_m_s",
        families: SHIP,
        unit: "m/s",
        default: "no wind",
        description: "A wind's mean speed, fixed in direction (wind_from_deg), on a ship with \
                      [windage]: the air relative to the ship is the wind's velocity less the \
                      ship's over ground, and its loads (X, Y, N, about midship) change with \
                      the heading, so a turning circle drifts (drift_m_per_turn …, as in a \
                      current), no IMO criterion is judged, and a spiral is refused. Every \
                      manoeuvre starts from the approach, heading north, with the wind acting \
                      from t = 0.",
        example: "20.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "environment.wind_from_deg",
        families: SHIP,
        unit: "deg",
        required: Required::When("with environment.wind_m_s"),
        description: "The direction the wind blows from (as winds are given), clockwise from \
                      north (X): 90 blows from the east, toward the west.",
        example: "45.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "environment.wind_spectrum",
        families: SHIP,
        kind: Kind::Text(Choices::These(&["norsok"])),
        default: "a steady wind",
        description: "Gusts: the wind's speed fluctuates about wind_m_s (the one-hour mean at \
                      10 m) as a sum of 250 harmonics up to 0.5 Hz drawn from NORSOK N-003's \
                      spectrum with wind_seed (the direction stays the mean's). summary.json \
                      gives the series' σ beside the whole spectrum's.",
        example: "\"norsok\"",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "environment.wind_seed",
        families: SHIP,
        kind: Kind::Integer,
        required: Required::When("with environment.wind_spectrum"),
        description: "The seed the gusts' frequencies and phases are drawn with (ChaCha8): one \
                      seed, one series, on every machine.",
        example: "7",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "environment.wind_height_m",
        families: SHIP,
        unit: "m",
        default: "10",
        description: "The height above the sea the gust spectrum is taken at.",
        example: "10.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    // [windage]
    Key {
        path: "windage.coefficients",
        families: SHIP,
        kind: Kind::Text(Choices::These(&["isherwood"])),
        default: "a table: angles_deg, C_X, C_Y, C_N",
        description: "The ship's wind coefficients over the angle off the bow the relative \
                      wind comes from: \"isherwood\" computes them by Isherwood's regression \
                      (1972; data/isherwood1972.json) from beam_m, superstructure_area_m2, \
                      perimeter_m, centroid_from_bow_m and masts; left out, the table \
                      angles_deg, C_X, C_Y, C_N gives them. The loads are X = ½ρ_a V² C_X A_F, \
                      Y = ½ρ_a V² C_Y A_L, N = ½ρ_a V² C_N A_L L_oa, about midship.",
        example: "\"isherwood\"",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "windage.angles_deg",
        families: SHIP,
        kind: Kind::Numbers("angles off the bow, 0 first, 180 last, increasing"),
        required: Required::When("without coefficients = \"isherwood\""),
        description: "The table's angles: the wind from ahead (0) to astern (180), the same \
                      from either side; the coefficients are linear between them.",
        example: "[0.0, 90.0, 180.0]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "windage.C_X",
        families: SHIP,
        kind: Kind::Numbers("one per angle"),
        required: Required::When("with windage.angles_deg"),
        description: "C_X at each angle, positive forward (a head wind's is negative), on \
                      the frontal area.",
        example: "[-0.6, 0.0, 0.5]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "windage.C_Y",
        families: SHIP,
        kind: Kind::Numbers("one per angle, 0 at 0 and 180"),
        required: Required::When("with windage.angles_deg"),
        description: "C_Y at each angle, on the lateral area, in the published convention: \
                      positive for a wind from port, which pushes the ship to starboard (eom \
                      turns it for a wind from starboard).",
        example: "[0.0, 0.8, 0.0]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "windage.C_N",
        families: SHIP,
        kind: Kind::Numbers("one per angle, 0 at 0 and 180"),
        required: Required::When("with windage.angles_deg"),
        description: "C_N at each angle, on the lateral area times L_oa, positive for a wind \
                      from port turning the bow to starboard.",
        example: "[0.0, 0.05, 0.0]",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "windage.length_overall_m",
        families: SHIP,
        unit: "m",
        required: Required::When("with [windage]"),
        description: "L_oa, the length overall: the wind's moment's length (and Isherwood's L).",
        example: "171.8",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "windage.frontal_area_m2",
        families: SHIP,
        unit: "m²",
        required: Required::When("with [windage]"),
        description: "A_F, the frontal projected area above water.",
        example: "320.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "windage.lateral_area_m2",
        families: SHIP,
        unit: "m²",
        required: Required::When("with [windage]"),
        description: "A_L, the lateral projected area above water.",
        example: "1450.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "windage.air_density_kg_m3",
        families: SHIP,
        unit: "kg/m³",
        default: "1.225",
        description: "ρ_a, the air's density (the standard atmosphere's at sea level).",
        example: "1.225",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "windage.beam_m",
        families: SHIP,
        unit: "m",
        required: Required::When("with coefficients = \"isherwood\""),
        description: "B, the beam, for Isherwood's regression.",
        example: "23.17",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "windage.superstructure_area_m2",
        families: SHIP,
        unit: "m²",
        required: Required::When("with coefficients = \"isherwood\""),
        description: "A_SS, the superstructure's lateral projected area, for Isherwood's \
                      regression.",
        example: "450.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "windage.perimeter_m",
        families: SHIP,
        unit: "m",
        required: Required::When("with coefficients = \"isherwood\""),
        description: "S, the perimeter of the lateral projection, the waterline and slender \
                      bodies (masts, ventilators) left out, for Isherwood's regression.",
        example: "220.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "windage.centroid_from_bow_m",
        families: SHIP,
        unit: "m",
        required: Required::When("with coefficients = \"isherwood\""),
        description: "C, the lateral area's centroid's distance from the bow, for Isherwood's \
                      regression.",
        example: "90.0",
        shown: Shown::Commented,
        ..Key::BLANK
    },
    Key {
        path: "windage.masts",
        families: SHIP,
        kind: Kind::Integer,
        required: Required::When("with coefficients = \"isherwood\""),
        description: "M, the groups of masts or king posts seen in lateral projection (king \
                      posts against the bridge front not counted), for Isherwood's regression.",
        example: "4",
        shown: Shown::Commented,
        ..Key::BLANK
    },
];
