"""shipmmg (PyPI 0.0.11) on the KVLCC2 at L = 7 m, run as eom runs scenes/kvlcc2_l7.toml:
peer/mmg/shipmmg_kvlcc2.py runs every trial again, under shipmmg as published, under a copy of
its right-hand side with each of its three differences from eom's model switched to eom's
reading, and under eom (the binary EOM_BIN names), and fails if a figure has moved from
peer/mmg/shipmmg_kvlcc2.json by more than 1e-6 of its value: docs/mmg.md's comparison, in
which the copy with every switch at eom's reading gives eom's figures, cannot drift from
either program."""

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_shipmmg_and_eom_give_the_figures_the_comparison_holds():
    script = ROOT / "peer" / "mmg" / "shipmmg_kvlcc2.py"
    assert os.environ.get("EOM_BIN"), "EOM_BIN names the eom binary the comparison runs"
    done = subprocess.run([sys.executable, str(script), "--check"], capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "not built" not in done.stdout, done.stdout
