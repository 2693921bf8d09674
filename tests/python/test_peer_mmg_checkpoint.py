"""peer/mmg/checkpoints.json is what peer/mmg/checkpoint.py writes from data/kvlcc2_mmg.json:
the table tests/mmg_forces.rs holds eom's MMG forces to cannot drift from the script that
works the paper's equations."""

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_the_mmg_checkpoints_are_what_the_script_writes():
    script = ROOT / "peer" / "mmg" / "checkpoint.py"
    done = subprocess.run([sys.executable, str(script), "--check"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
