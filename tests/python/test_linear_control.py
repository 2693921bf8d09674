"""`eom linear --out` read as GNC engineers read it: linear.json into python-control, linear.mat
into scipy (as MATLAB's `load` reads it), for REMUS 100 at cruise and the Mariner on a straight
course.

The binary is $EOM_BIN, by default target/debug/eom (what `cargo test` builds).
"""

import json
import os
import subprocess
from pathlib import Path

import control
import numpy as np
import pytest
import scipy.io

ROOT = Path(__file__).resolve().parents[2]
EOM = Path(os.environ.get("EOM_BIN", ROOT / "target" / "debug" / "eom"))

# Both sides compute the eigenvalues of the same A (linear.json's numbers read back to A's bits)
# with backward-stable solvers: nalgebra's real Schur form and LAPACK's dgeev. Each gives the
# exact eigenvalues of A + E with |E| ~ 1e-16 |A|, so an eigenvalue moves by at most its
# condition number times that. 1e-9 of |A| leaves a factor of 10^6 for the condition number;
# the scenes' eigenvalues are simple and agree to 3e-15 of |A| (docs/linear.md).
EIGENVALUE_TOLERANCE = 1e-9

SCENES = ["remus100.toml", "mariner.toml"]


@pytest.fixture(scope="module", params=SCENES)
def written(request, tmp_path_factory):
    """The folder `eom linear SCENE --out` wrote."""
    out = tmp_path_factory.mktemp(request.param.removesuffix(".toml")) / "linear"
    scene = ROOT / "scenes" / request.param
    run = subprocess.run(
        [str(EOM), "linear", str(scene), "--out", str(out)],
        capture_output=True,
        text=True,
    )
    assert run.returncode == 0, run.stderr
    return out


def read_json(written):
    return json.loads((written / "linear.json").read_text())


def state_space(model):
    """The snippet of docs/linear.md."""
    return control.ss(
        model["A"],
        model["B"],
        model["C"],
        model["D"],
        inputs=model["u_names"],
        outputs=model["y_names"],
        states=model["x_names"],
    )


def test_control_reads_the_names(written):
    model = read_json(written)
    sys = state_space(model)
    assert [sys.state_labels, sys.input_labels, sys.output_labels] == [
        model["x_names"],
        model["u_names"],
        model["y_names"],
    ]


def test_control_damp_gives_eoms_modes(written):
    model = read_json(written)
    wn, zeta, poles = control.damp(state_space(model), doprint=False)
    size = np.linalg.norm(np.array(model["A"]), 2)
    tolerance = EIGENVALUE_TOLERANCE * size
    assert len(poles) == len(model["eigenvalues"])
    # Each of eom's modes (one per real eigenvalue or conjugate pair) against control's
    # nearest pole: the eigenvalue, the natural frequency |λ| and the damping ratio −Re λ/|λ|.
    for mode in model["modes"]:
        eigenvalue = complex(mode["re"], mode["im"])
        k = np.argmin(np.abs(poles - eigenvalue))
        assert abs(poles[k] - eigenvalue) <= tolerance, (poles[k], eigenvalue)
        assert abs(wn[k] - abs(eigenvalue)) <= tolerance, (wn[k], eigenvalue)
        # dζ = d(Re λ)/|λ| + Re λ d|λ|/|λ|², at most 2|dλ|/|λ|.
        assert abs(zeta[k] - mode["damping_ratio"]) <= 2 * tolerance / abs(eigenvalue), (
            zeta[k],
            mode["damping_ratio"],
        )
    # And every pole is one of eom's eigenvalues, conjugates included.
    eom = np.array([complex(e["re"], e["im"]) for e in model["eigenvalues"]])
    for pole in poles:
        assert np.min(np.abs(eom - pole)) <= tolerance, pole


def bits(array):
    return np.ascontiguousarray(array, dtype=np.float64).view(np.uint64)


def texts(cells):
    """A MAT-file's cell array of strings as scipy reads it: an object array of char arrays."""
    return [str(cell[0]) if cell.size else "" for cell in cells.ravel()]


def test_loadmat_reads_the_same_model_bit_for_bit(written):
    model = read_json(written)
    mat = scipy.io.loadmat(written / "linear.mat")
    for key in ["A", "B", "C", "D"]:
        expected = np.array(model[key], dtype=np.float64)
        assert mat[key].shape == expected.shape, key
        assert np.array_equal(bits(mat[key]), bits(expected)), key
    for key in ["x0", "u0", "set_aside_values"]:
        expected = np.array(model[key], dtype=np.float64).reshape(-1, 1)
        assert np.array_equal(bits(mat[key].reshape(-1, 1)), bits(expected)), key
    for key in ["x_names", "u_names", "y_names", "x_units", "u_units", "y_units"]:
        assert texts(mat[key]) == model[key], key
    for key in ["set_aside", "set_aside_why"]:
        assert texts(mat[key]) == model[key], key
    for key in ["scene", "title", "jacobians"]:
        assert str(mat[key][0]) == model[key], key
