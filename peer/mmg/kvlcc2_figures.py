#!/usr/bin/env python3
"""The KVLCC2's manoeuvring figures under eom's MMG model, beside the paper's.

Runs `eom run` on scenes/kvlcc2_l7.toml and scenes/kvlcc2_full.toml (SIMMAN 2020's setup: the
propeller at the rate that balances the approach, solved) and on two variants of the model
scale that change only the setup (the propeller held at the free-running tests' measured
10.33 rev/s; that and the paper's rudder rate, 1.76 deg/s at full scale = 11.9 deg/s at L7),
and prints docs/mmg.md's table: each figure over L (or in degrees, or in seconds at model
scale), port and starboard, beside the paper's simulated and free-running values.

The paper's values (H. Yasukawa and Y. Yoshimura 2015, J. Mar. Sci. Technol. 20:37-52,
Tables 4 and 5: "Cal." its MMG simulation, "Exp." MARIN's free-running tests of the 7 m
model) are as public transcriptions give them; the paper itself was not read here. MARIN's
SIMMAN 2008 free-running records of the L7 model give the Exp. values again to 0.05 L and
0.05 deg. The paper's propeller rate is not in those transcriptions ("held at the value
corresponding to the initial speed").

    python3 peer/mmg/kvlcc2_figures.py [path/to/eom]     (default target/release/eom)
"""

import json
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]

# Yasukawa & Yoshimura (2015), Tables 4 and 5, as transcribed: (Cal., Exp.); None where the
# transcriptions give none. "+35 deg" and "+10/+10" are to starboard.
PAPER = {
    ("advance_90_m", "starboard"): (3.31, 3.25),
    ("tactical_diameter_m", "starboard"): (3.36, 3.34),
    ("advance_90_m", "port"): (3.26, 3.11),
    ("tactical_diameter_m", "port"): (3.26, 3.08),
    ("zigzag_10_10.first_overshoot_deg", "starboard"): (5.2, 8.2),
    ("zigzag_10_10.second_overshoot_deg", "starboard"): (15.8, 21.9),
    ("zigzag_20_20.first_overshoot_deg", "starboard"): (10.9, 13.7),
    ("zigzag_10_10.first_overshoot_deg", "port"): (7.6, 9.5),
    ("zigzag_10_10.second_overshoot_deg", "port"): (10.2, 15.0),
    ("zigzag_20_20.first_overshoot_deg", "port"): (14.5, 15.1),
}

TURNING = ["advance_90_m", "transfer_90_m", "tactical_diameter_m", "steady_turning_radius_m"]
TIMES = ["t_90_s", "t_180_s"]
ZIGZAG = [
    "zigzag_10_10.first_overshoot_deg",
    "zigzag_10_10.second_overshoot_deg",
    "zigzag_20_20.first_overshoot_deg",
    "zigzag_20_20.second_overshoot_deg",
]


def variant(text, changes):
    for old, new in changes:
        if old not in text:
            sys.exit(f"the scene no longer holds {old!r}")
        text = text.replace(old, new, 1)
    return text


def run(eom, text, folder):
    scene = folder / "scene.toml"
    scene.write_text(text)
    out = folder / "out"
    subprocess.run(
        [eom, "run", str(scene), "--out", str(out), "--force"],
        check=True,
        capture_output=True,
    )
    return json.loads((out / "summary.json").read_text())


def figure(summary, key, side):
    manoeuvre, _, name = key.rpartition(".")
    manoeuvre = manoeuvre or "turning_circle_35"
    value = summary["manoeuvre"][manoeuvre]["sides"][side].get(name)
    return value


def main():
    eom = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "target/release/eom")
    l7 = (ROOT / "scenes/kvlcc2_l7.toml").read_text()
    full = (ROOT / "scenes/kvlcc2_full.toml").read_text()
    rate = ("design_speed = 1.179          # U₀, m/s: Fn = 0.142",
            "design_speed = 1.179\npropeller_rate_rps = 10.33")
    gear = ("max_rate_deg_s = 15.68        # SIMMAN 2020, model scale",
            "max_rate_deg_s = 11.9")
    runs = [
        ("L7, n₀ solved, 15.68°/s", l7, 7.0, 1.0),
        ("full, n₀ solved, 2.32°/s", full, 320.0, (320.0 / 7.0) ** 0.5),
        ("L7, n = 10.33 rev/s, 15.68°/s", variant(l7, [rate]), 7.0, 1.0),
        ("L7, n = 10.33 rev/s, 11.9°/s", variant(l7, [rate, gear]), 7.0, 1.0),
    ]
    results = []
    with tempfile.TemporaryDirectory() as temporary:
        for k, (label, text, length, time_scale) in enumerate(runs):
            folder = pathlib.Path(temporary) / str(k)
            folder.mkdir()
            summary = run(eom, text, folder)
            rate_held = summary["model"]["mmg"]["approach_rate_rps"]
            results.append((f"{label} (n = {rate_held:.4g})", summary, length, time_scale))
    header = ["figure", "side"] + [label for label, *_ in results] + ["paper Cal.", "Exp."]
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * 2 + "---:|" * (len(header) - 2))
    rows = [(key, "/L") for key in TURNING] + [(key, " s (L7)") for key in TIMES]
    rows += [(key, " °") for key in ZIGZAG]
    for key, unit in rows:
        for side in ["port", "starboard"]:
            cells = []
            for _, summary, length, time_scale in results:
                value = figure(summary, key, side)
                if value is None:
                    cells.append("—")
                elif unit == "/L":
                    cells.append(f"{value / length:.2f}")
                elif unit.startswith(" s"):
                    cells.append(f"{value / time_scale:.1f}")
                else:
                    cells.append(f"{value:.1f}")
            cal, exp = PAPER.get((key, side), (None, None))
            cells += ["—" if cal is None else str(cal), "—" if exp is None else str(exp)]
            name = key.replace("zigzag_", "").replace("_deg", "").replace("_m", "")
            print(f"| {name}{unit} | {side} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
