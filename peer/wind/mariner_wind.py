#!/usr/bin/env python3
"""The Mariner's 35 deg turning circle in a 20 m/s wind: docs/ships.md's table.

Builds from scenes/mariner.toml (its spiral left out: a spiral is refused in a wind) the
scenes of the table, each with the Mariner's windage of tests/support/mariner_windage.toml
(Isherwood's regression at an estimated geometry, which that file explains) but the first:
still water and no air; still air (the ship's own air resistance); a steady wind of 20 m/s
from the west (270 deg, across the approach from port); the same wind gusting from NORSOK's
spectrum with seeds 7 and 8. Runs `eom run` on each and prints the turning circle's figures
to both sides.

    python3 peer/wind/mariner_wind.py [path/to/eom]     (default target/release/eom)
"""

import json
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]

CASES = [
    ("still water, no air", None),
    ("still air", ""),
    ("20 m/s from 270 deg", "wind_m_s = 20.0\nwind_from_deg = 270.0\n"),
    (
        "gusting, seed 7",
        'wind_m_s = 20.0\nwind_from_deg = 270.0\nwind_spectrum = "norsok"\nwind_seed = 7\n',
    ),
    (
        "gusting, seed 8",
        'wind_m_s = 20.0\nwind_from_deg = 270.0\nwind_spectrum = "norsok"\nwind_seed = 8\n',
    ),
]

FIGURES = [
    ("advance_90_m", "advance, m", 1),
    ("transfer_90_m", "transfer, m", 1),
    ("tactical_diameter_m", "tactical diameter, m", 1),
    ("drift_m_per_turn", "drift per turn, m", 1),
    ("drift_toward_deg", "drift toward, deg", 1),
    ("turn_period_s", "turn period, s", 1),
]


def scene(environment):
    """scenes/mariner.toml without its spiral, with `environment` and the windage."""
    text = (ROOT / "scenes" / "mariner.toml").read_text()
    start = text.index("# Dieudonné's direct spiral")
    end = text.index("# `eom linear` about")
    text = text[:start] + text[end:]
    if environment is None:
        return text
    windage = (ROOT / "tests" / "support" / "mariner_windage.toml").read_text()
    added = f"[environment]\n{environment}\n{windage}\n[integrator]"
    return text.replace("[integrator]", added, 1)


def main():
    eom = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "target" / "release" / "eom")
    columns = []
    with tempfile.TemporaryDirectory() as tmp:
        for k, (name, environment) in enumerate(CASES):
            path = pathlib.Path(tmp) / f"case{k}.toml"
            path.write_text(scene(environment))
            out = pathlib.Path(tmp) / f"out{k}"
            subprocess.run([eom, "run", str(path), "--out", str(out)], check=True,
                           stdout=subprocess.DEVNULL)
            summary = json.loads((out / "summary.json").read_text())
            columns.append((name, summary["manoeuvre"]["turning_circle_35"]["sides"]))
    for side in ["port", "starboard"]:
        print(f"\n{side}:\n")
        print("| figure | " + " | ".join(name for name, _ in columns) + " |")
        print("|---|" + "---:|" * len(columns))
        for key, label, digits in FIGURES:
            cells = []
            for _, sides in columns:
                value = sides[side].get(key)
                cells.append("—" if value is None else f"{value:.{digits}f}")
            print(f"| {label} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
