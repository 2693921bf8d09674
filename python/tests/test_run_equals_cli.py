"""Every example scene run from Python gives what `eom run` writes, bit for bit: each run's
trajectory.csv parsed (its numbers are written in the shortest form that reads back to the
same double, so float() of each cell is the double the run computed) against the arrays, its
header against the columns, and summary.json read by json.load against the summary dict,
the wall-clock time aside."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import numpy as np
import pytest

import eom

from conftest import SCENES, eom_cli

# Each scene takes at most a few seconds through the debug binary (the Esso Osaka, the
# longest, about 6 s with its plots); all run.
# A Monte Carlo's scene (an [uncertainty] table) is left out: `eom run` runs its cases into a
# table of their figures, where Python runs the scene as written (tests/uncertainty.rs and
# app/tests/cli_uncertainty.rs hold the cases).
SCENE_FILES = sorted(
    p.name for p in SCENES.glob("*.toml") if "\n[uncertainty]\n" not in p.read_text()
)

# Keys of the summary that measure the run's wall-clock time, not what it computed.
WALL_CLOCK = {"wall_seconds"}


def without_wall_clock(value):
    if isinstance(value, dict):
        return {k: without_wall_clock(v) for k, v in value.items() if k not in WALL_CLOCK}
    if isinstance(value, list):
        return [without_wall_clock(v) for v in value]
    return value


def bits(array: np.ndarray) -> np.ndarray:
    return np.ascontiguousarray(array, dtype=np.float64).view(np.uint64)


def same_bits(a: np.ndarray, b: np.ndarray) -> bool:
    """Equal double for double; a NaN equals a NaN (Rust writes every NaN as `NaN`)."""
    nan = np.isnan(a)
    return (
        a.shape == b.shape
        and np.array_equal(nan, np.isnan(b))
        and np.array_equal(bits(np.where(nan, 0.0, a)), bits(np.where(nan, 0.0, b)))
    )


def read_csv(path: Path) -> tuple[list[str], np.ndarray]:
    with path.open(newline="") as file:
        rows = list(csv.reader(file))
    return rows[0], np.array([[float(cell) for cell in row] for row in rows[1:]], dtype=np.float64)


@pytest.mark.parametrize("name", SCENE_FILES)
def test_a_scene_run_from_python_equals_eom_run(name, binary, tmp_path):
    scene_path = str(SCENES / name)
    out = tmp_path / "out"
    eom_cli("run", scene_path, "--out", str(out))
    result = eom.Scene.load(scene_path).run()

    written = {
        str(path.parent.relative_to(out)).replace("\\", "/").removeprefix("."): path
        for path in out.rglob("trajectory.csv")
    }
    assert sorted(written) == sorted(result.trajectories), name
    for run_path, csv_path in written.items():
        header, rows = read_csv(csv_path)
        trajectory = result.trajectories[run_path]
        assert trajectory.columns == header, run_path
        assert same_bits(trajectory.data, rows), run_path

    summary = json.loads((out / "summary.json").read_text())
    # json.dumps of each: equal text is equal keys, order and numbers (each number read from
    # its shortest decimal, so equal text is equal bits).
    assert json.dumps(without_wall_clock(result.summary)) == json.dumps(without_wall_clock(summary))


def test_one_manoeuvre_runs_alone_as_in_the_whole_scene(binary, tmp_path):
    """`run("zigzag_10_10")` gives that manoeuvre's rows as the whole scene's run gives them:
    each manoeuvre starts from the same approach."""
    scene = eom.Scene.load(SCENES / "mariner.toml")
    out = tmp_path / "out"
    eom_cli("run", str(SCENES / "mariner.toml"), "--out", str(out))
    alone = scene.run("zigzag_10_10")
    assert sorted(alone.trajectories) == ["zigzag_10_10/port", "zigzag_10_10/starboard"]
    for path, trajectory in alone.trajectories.items():
        header, rows = read_csv(out / path / "trajectory.csv")
        assert trajectory.columns == header
        assert same_bits(trajectory.data, rows), path
    whole = json.loads((out / "summary.json").read_text())
    assert "turning_circle_35" in whole["manoeuvre"]
    assert "turning_circle_35" not in alone.summary["manoeuvre"]
    assert alone.summary["manoeuvre"]["zigzag_10_10"] == whole["manoeuvre"]["zigzag_10_10"]
    with pytest.raises(eom.SceneError) as refused:
        scene.run("zigzag_99")
    assert refused.value.key == "manoeuvre"
    assert "turning_circle_35" in refused.value.message
