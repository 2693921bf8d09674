"""The model from Python: rhs(x, u) and its Jacobians over many states in one call, against
the Rust call (`eom eval` and the single-state call), an independent numpy form of 4.46 and
finite differences."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import pytest

import eom

from conftest import ROOT, SCENES, eom_cli

sys.path.insert(0, str(ROOT / "python" / "benchmarks"))
from mariner_numpy import Mariner, random_states  # noqa: E402


@pytest.fixture(scope="module")
def mariner():
    return eom.Scene.load(SCENES / "mariner.toml").model()


def test_the_models_names(mariner):
    assert mariner.name == "ship"
    assert mariner.state_names == ["u", "v", "r", "X", "Y", "psi", "delta"]
    assert mariner.input_names == ["delta_rate", "n", "wind_gust"]


def test_rhs_over_a_million_states_in_one_call_is_each_states_own_call(mariner):
    """10⁶ states in one call: each column is the single-state call's rates, bit for bit, and
    the numpy form of 4.46 (written by hand) agrees to rounding."""
    x, u = random_states(10**6)
    rates = mariner.rhs(x, u)
    assert rates.shape == (7, 10**6) and rates.dtype == np.float64
    for k in np.random.default_rng(2).integers(0, 10**6, 200):
        assert np.array_equal(mariner.rhs(x[:, k], u[:, k]), rates[:, k])
    # Rounding: each rate is a sum of about 40 products of order its largest value, each
    # rounded at 1.1e-16; the two forms order them differently. 1e-13 of the largest
    # magnitude of each rate leaves a factor of 20 over 40 roundings' worst case.
    numpy_rates = Mariner().rhs(x, u)
    scale = np.abs(rates).max(axis=1, keepdims=True)
    assert np.max(np.abs(rates - numpy_rates) / scale) < 1e-13


BODY = """
title = "A body with every product of inertia"
[body]
mass = 2.0
inertia = [[2.0, -0.1, 0.2], [-0.1, 3.0, 0.05], [0.2, 0.05, 4.0]]
[model]
family = "spatial"
symmetry = "full"
kinematics = "euler"
[integrator]
method = "rk4"
step = 0.01
end_time = 1.0
"""


def test_a_catalog_model_is_eom_evals_generated_call_bit_for_bit(binary, tmp_path):
    """A spatial body's model (full symmetry, Euler angles) from Python against `eom eval`,
    the binary's call of the same generated model, which prints each rate's shortest
    decimal."""
    model = eom.Scene.from_text(BODY).model()
    assert model.name == "spatial_full_euler"
    rng = np.random.default_rng(3)
    x = rng.uniform(-1.2, 1.2, (12, 5))
    u = rng.uniform(-1, 1, (6, 5))
    rates = model.rhs(x, u)
    for k in range(5):
        state = dict(zip(model.state_names, x[:, k].tolist()))
        given = {
            "mass": 2.0,
            "inertia": [[2.0, -0.1, 0.2], [-0.1, 3.0, 0.05], [0.2, 0.05, 4.0]],
            "state": {name: state[name] for name in ["u", "v", "w", "p", "q", "r", "phi", "theta", "psi"]},
            "force": u[:3, k].tolist(),
            "moment": u[3:, k].tolist(),
        }
        path = tmp_path / f"state{k}.json"
        path.write_text(json.dumps(given))
        printed = eom_cli(
            "eval", "--model", "spatial", "--symmetry", "full",
            "--kinematics", "euler", "--input", str(path),
        )
        generated = json.loads(printed.stdout)["generated"]
        assert list(generated) == [f"{name}_dot" for name in model.state_names]
        assert np.array_equal(np.array(list(generated.values())), rates[:, k]), k


def test_the_jacobians_are_the_derivatives_of_the_rates(mariner):
    """∂f/∂x and ∂f/∂u at 20 states, vectorised, against central differences of rhs: the
    difference's error is h² f‴/6 + ε|f|/h, about 1e-8 relative at h = 1e-5 of each entry's
    scale; 1e-6 leaves a hundredfold margin."""
    x, u = random_states(20, seed=4)
    a, b = mariner.state_jacobian(x, u), mariner.input_jacobian(x, u)
    assert a.shape == (7, 7, 20) and b.shape == (7, 3, 20)
    for k in range(20):
        assert np.array_equal(mariner.state_jacobian(x[:, k], u[:, k]), a[:, :, k])
    scale = np.abs(mariner.rhs(x, u)).max(axis=1) + 1e-300
    for j in range(7):
        h = 1e-5 * max(1.0, np.abs(x[j]).max())
        up, down = x.copy(), x.copy()
        up[j] += h
        down[j] -= h
        difference = (mariner.rhs(up, u) - mariner.rhs(down, u)) / (2 * h)
        assert np.all(np.abs(difference - a[:, j, :]) <= 1e-6 * (scale[:, None] + np.abs(a[:, j, :]))), j


def test_wrong_shapes_and_values_are_exceptions_that_say_so(mariner):
    x, u = random_states(4)
    with pytest.raises(eom.ShapeError, match=r"\(7, N\)"):
        mariner.rhs(x[:6], u)
    with pytest.raises(eom.ShapeError, match=r"u has shape \(3, 3\)"):
        mariner.rhs(x, u[:, :3])
    with pytest.raises(eom.ShapeError):
        mariner.rhs(np.zeros((7, 2, 2)), u)
    with pytest.raises(ValueError):  # ShapeError is a ValueError too
        mariner.rhs(x, [0.0])
    x[2, 3] = np.nan
    with pytest.raises(eom.InvalidValue, match=r"x\[2, 3\] \(r\) is NaN"):
        mariner.rhs(x, u)
    x[2, 3] = 0.0
    u[1, 0] = np.inf
    with pytest.raises(eom.InvalidValue, match=r"u\[1, 0\] \(n\) is inf"):
        mariner.state_jacobian(x, u)


def test_the_f16s_model_at_its_trim_gives_eom_linears_a_and_b(binary):
    """The aircraft's model from Python, at the operating point `eom linear scenes/f16.toml`
    reports (its reduced state, with the states set aside at their values): the rates of the
    kept states are the trim's residual, and its proved Jacobians, restricted to the kept
    states, are the A and B the command prints, bit for bit (the same call behind both)."""
    scene = eom.Scene.load(SCENES / "f16.toml")
    model = scene.model()
    assert model.name == "aircraft"
    assert model.input_names == ["throttle", "elevator", "aileron", "rudder"]
    linear = json.loads(eom_cli("linear", str(SCENES / "f16.toml"), "--json").stdout)
    point = dict(zip(linear["x_names"], linear["x0"]))
    point.update(zip(linear["set_aside"], linear["set_aside_values"]))
    x = np.array([point[name] for name in model.state_names])
    u = np.array(linear["u0"])
    kept = [model.state_names.index(name) for name in linear["x_names"]]
    rates = model.rhs(x, u)
    residual = np.array([linear["residual"][name] for name in linear["x_names"]])
    assert np.array_equal(rates[kept], residual)
    a = model.state_jacobian(x, u)
    assert np.array_equal(a[np.ix_(kept, kept)], np.array(linear["A"]))
    b = model.input_jacobian(x, u)
    assert np.array_equal(b[kept, :], np.array(linear["B"]))
