"""Linearisation, the derivation and the mass properties from Python against the binary's;
a sweep as a Python loop against `eom run`'s; errors as exceptions with eom's message and key
path; a run that releases the GIL and stops on Ctrl-C."""

from __future__ import annotations

import json
import signal
import subprocess
import threading
import time

import numpy as np
import pytest

import eom

from conftest import EOM, ROOT, SCENES, eom_cli


def bits(array) -> np.ndarray:
    return np.ascontiguousarray(array, dtype=np.float64).view(np.uint64)


@pytest.mark.parametrize("name", ["remus100.toml", "mariner.toml", "heavy_top.toml"])
def test_linearise_gives_eom_linears_report_bit_for_bit(name, binary):
    path = str(SCENES / name)
    printed = json.loads(eom_cli("linear", path, "--json").stdout)
    linear = eom.Scene.load(path).linearise()
    assert linear.json == printed
    for key in ["A", "B", "C", "D"]:
        expected = np.array(printed[key], dtype=np.float64).reshape(getattr(linear, key).shape)
        assert np.array_equal(bits(getattr(linear, key)), bits(expected)), key
    assert linear.x_names == printed["x_names"] and linear.u_names == printed["u_names"]
    assert linear.report == eom_cli("linear", path).stdout


def test_remus_modes_through_python_control():
    """The snippet of docs/python.md: REMUS's linear model as a python-control StateSpace,
    its poles eom's eigenvalues (both backward-stable eigensolvers on the same A: 1e-9 of
    |A|, as tests/python/test_linear_control.py argues)."""
    control = pytest.importorskip("control")
    linear = eom.Scene.load(SCENES / "remus100.toml").linearise()
    sys = linear.state_space()
    assert isinstance(sys, control.StateSpace)
    assert sys.state_labels == linear.x_names and sys.input_labels == linear.u_names
    wn, zeta, poles = control.damp(sys, doprint=False)
    tolerance = 1e-9 * np.linalg.norm(linear.A, 2)
    for eigenvalue in linear.eigenvalues:
        assert np.min(np.abs(poles - eigenvalue)) <= tolerance


def test_derive_is_eom_derives_report():
    derivation = eom.derive()
    assert derivation.all_proved and len(derivation.equations) > 10
    assert any(e.number == "4.46" for e in derivation.equations)


def test_derive_markdown_is_what_eom_derive_prints(binary):
    assert eom.derive().markdown == eom_cli("derive").stdout


def test_mass_is_eom_mass_json(binary):
    body = SCENES / "bodies" / "ship_blocks.toml"
    printed = json.loads(eom_cli("mass", str(body), "--json", "--about", "0,0,0").stdout)
    assert eom.mass(body, about=[0, 0, 0]) == printed
    assert eom.mass(body)["about"] is None


SWEPT = """
title = "Pendulum, a sweep of its length"
[model]
family = "pendulum"
[body]
i0 = 2.0
mass = 3.0
g = 9.81
h = 0.5
[initial]
theta_deg = 30.0
[integrator]
method = "dop853"
rtol = 1e-10
end_time = 5.0
[output]
every = 0.05
[sweep]
"body.h" = [0.4, 0.5]
"""


def test_a_sweep_in_a_python_loop_is_eoms_sweep(binary, tmp_path):
    """The cases from Python (`with_values` in a loop, and `cases()`) run to the same rows as
    `eom run`'s case folders."""
    path = tmp_path / "swept.toml"
    path.write_text(SWEPT)
    out = tmp_path / "out"
    eom_cli("run", str(path), "--out", str(out))
    scene = eom.Scene.load(path)
    cases = scene.cases()
    assert [c.values for c in cases] == [{"body.h": 0.4}, {"body.h": 0.5}]
    for case in cases:
        looped = scene.with_values({"body.h": case.values["body.h"]}).run()
        from_case = case.scene.run()
        written = np.genfromtxt(out / f"case-{case.index:04d}" / "trajectory.csv", delimiter=",", skip_header=1)
        assert np.array_equal(bits(looped.trajectory.data), bits(written))
        assert np.array_equal(bits(from_case.trajectory.data), bits(written))
        summary = json.loads((out / f"case-{case.index:04d}" / "summary.json").read_text())
        assert looped.summary["period_s"] == summary["period_s"]


def test_a_malformed_scene_is_a_scene_error_with_its_key():
    text = (SCENES / "pendulum.toml").read_text().replace("[integrator]", "[integrator]\nstep = -1.0", 1)
    with pytest.raises(eom.SceneError) as error:
        eom.Scene.from_text(text, name="bad.toml")
    assert error.value.key is not None and error.value.key.startswith("integrator")
    assert error.value.file == "bad.toml"
    assert error.value.message == str(error.value)
    with pytest.raises(eom.SceneError) as error:
        eom.Scene.from_text("title = [", name="broken.toml")
    assert "TOML" in error.value.message and error.value.key is None
    with pytest.raises(eom.SceneError) as error:
        eom.Scene.load(SCENES / "mariner.toml").with_values({"hydrodynamics.design_speed": "fast"})
    assert error.value.key == "hydrodynamics.design_speed"


def test_a_missing_file_is_a_file_error():
    with pytest.raises(eom.FileError) as error:
        eom.Scene.load(ROOT / "scenes" / "no_such_scene.toml")
    assert isinstance(error.value, OSError) and "cannot read" in error.value.message
    with pytest.raises(eom.FileError):
        eom.mass(ROOT / "no_such_body.toml")


def test_a_scene_knows_its_kind_runs_and_keys():
    mariner = eom.Scene.load(SCENES / "mariner.toml")
    assert (mariner.kind, mariner.title) == ("ship", "Mariner-class cargo ship")
    assert mariner.runs == ["turning_circle_35", "zigzag_10_10", "zigzag_20_20", "spiral"]
    assert "integrator.rtol" in mariner.keys and "manoeuvre[0].rudder_deg" in mariner.keys
    racket = eom.Scene.load(SCENES / "tennis_racket.toml")
    assert (racket.kind, racket.runs, racket.folders) == ("body", [], ["trajectory.csv"])


def test_a_run_releases_the_gil():
    """While a scene runs in one thread, another Python thread goes on."""
    scene = eom.Scene.load(SCENES / "esso_osaka.toml")
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(1)
            time.sleep(0.001)

    ticker = threading.Thread(target=tick)
    ticker.start()
    try:
        scene.run("pull_out_20")
    finally:
        done.set()
        ticker.join()
    assert len(ticks) > 10


def test_ctrl_c_stops_a_run_with_keyboard_interrupt():
    """SIGINT during the Esso Osaka's manoeuvres (seconds of work) stops the run at its next
    row and raises KeyboardInterrupt; the process goes on."""
    scene = eom.Scene.load(SCENES / "esso_osaka.toml")
    timer = threading.Timer(0.3, lambda: signal.raise_signal(signal.SIGINT))
    timer.start()
    # The run takes seconds; had it finished first, the interrupt would come after the block.
    with pytest.raises(KeyboardInterrupt):
        scene.run()
    timer.join()
    # The module is usable after it.
    assert eom.Scene.load(SCENES / "pendulum.toml").run().trajectory.t[-1] == 20.0


GIMBAL_LOCK = """
title = "Pitching through 90 degrees on Euler angles"
[body]
mass = 1.0
inertia = [[2.0, 0.0, 0.0], [0.0, 3.0, 0.0], [0.0, 0.0, 4.0]]
[model]
family = "spatial"
kinematics = "euler"
[initial]
rates = [0.0, 1.0, 0.0]
[integrator]
method = "rk4"
step = 0.01
end_time = 3.0
"""


def test_a_run_that_fails_raises_run_error_with_what_it_kept(binary, tmp_path):
    """Gimbal lock: `eom run` exits 5 keeping its rows and a summary with the error; Python
    raises RunError with the same rows and summary in `error.result`."""
    path = tmp_path / "gimbal.toml"
    path.write_text(GIMBAL_LOCK)
    out = tmp_path / "out"
    done = subprocess.run([str(EOM), "run", str(path), "--out", str(out)], capture_output=True)
    assert done.returncode == 5
    with pytest.raises(eom.RunError) as error:
        eom.Scene.load(path).run()
    assert "gimbal lock" in error.value.message
    kept = error.value.result
    written = np.genfromtxt(out / "trajectory.csv", delimiter=",", skip_header=1)
    assert np.array_equal(bits(kept.trajectory.data), bits(written))
    summary = json.loads((out / "summary.json").read_text())
    assert kept.summary["error"] == summary["error"] == error.value.message


def test_a_failed_manoeuvre_keeps_the_finished_figures_in_run_error_result(tmp_path):
    """The F-16 trimmed at 1500 ft/s: three of its manoeuvres dive through θ = −89°, two
    finish. `eom run` exits 5 with a summary holding the two and each failure; Python raises
    RunError whose result carries the same summary."""
    text = (SCENES / "f16.toml").read_text()
    path = tmp_path / "fast.toml"
    path.write_text(text.replace("speed = 502.0 # ft/s", "speed = 1500.0 # ft/s", 1))
    out = tmp_path / "out"
    done = subprocess.run([str(EOM), "run", str(path), "--out", str(out)], capture_output=True)
    assert done.returncode == 5
    with pytest.raises(eom.RunError) as error:
        eom.Scene.load(path).run()
    kept = error.value.result
    summary = json.loads((out / "summary.json").read_text())
    assert kept.summary["error"] == summary["error"] == error.value.message
    assert sorted(kept.summary["manoeuvre"]) == ["aileron_step", "rudder_kick"]
    assert kept.summary["manoeuvre"] == summary["manoeuvre"]


UNCERTAIN = SWEPT.replace(
    "[sweep]\n\"body.h\" = [0.4, 0.5]\n",
    "[uncertainty]\ncases = 12\nseed = 5\n\n[uncertainty.vary]\n"
    "\"body.h\" = { distribution = \"uniform\", low = 0.4, high = 0.6 }\n",
)


def test_a_monte_carlo_from_python_is_eoms_and_run_refuses_it(binary, tmp_path):
    """`Scene.run()` on a scene with `[uncertainty]` raises rather than running the scene
    as written; `Scene.monte_carlo()` gives the bytes `eom run` writes."""
    assert "[uncertainty]" in UNCERTAIN
    path = tmp_path / "uncertain.toml"
    path.write_text(UNCERTAIN)
    scene = eom.Scene.load(path)
    with pytest.raises(eom.SceneError) as raised:
        scene.run()
    assert raised.value.key == "uncertainty"
    assert "monte_carlo()" in str(raised.value)
    out = tmp_path / "out"
    eom_cli("run", str(path), "--out", str(out))
    result = scene.monte_carlo()
    written = json.loads((out / "uncertainty.json").read_text())
    assert result.report == written
    assert result.table == (out / "uncertainty.csv").read_text()
    assert result.report["cases"] == 12 and result.report["failed"] == []


def test_a_value_that_is_not_finite_is_refused_naming_its_key():
    """`with_values` hands each value to the scene's check as Python holds it: NaN is refused
    by the key it was given for, as the command refuses it in a scene file."""
    scene = eom.Scene.load(SCENES / "pendulum.toml")
    for value in (float("nan"), float("inf")):
        with pytest.raises(eom.SceneError) as raised:
            scene.with_values({"body.mass": value})
        assert raised.value.key == "body.mass", str(raised.value)
    assert scene.with_values({"body.mass": np.float64(4.0)}).table["body"]["mass"] == 4.0


def test_complex_states_are_refused_rather_than_cut_to_their_real_parts():
    model = eom.Scene.load(SCENES / "pendulum.toml").model()
    with pytest.raises(eom.InvalidValue, match="complex"):
        model.rhs(np.array([0.1 + 0.2j, 0.0]))
    with pytest.raises(eom.InvalidValue, match="complex"):
        model.state_jacobian([0.1, 0.0], u=np.zeros(len(model.input_names), dtype=complex))
    assert np.array_equal(model.rhs([0.1, 0.0]), model.rhs(np.array([0.1 + 0j, 0.0]).real))
