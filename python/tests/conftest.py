"""What the Python tests share: the repository, the `eom` binary the CLI's outputs come from
($EOM_BIN, by default target/debug/eom, which `cargo test --workspace` builds), and runs of
it."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SCENES = ROOT / "scenes"
# Resolved now, against the folder pytest was started in: a test may change folders.
EOM = Path(os.environ.get("EOM_BIN", ROOT / "target" / "debug" / "eom")).resolve()


def eom_cli(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess:
    """Runs the `eom` binary; fails the test with its standard error if it fails."""
    done = subprocess.run([str(EOM), *args], capture_output=True, text=True, cwd=cwd)
    assert done.returncode == 0, done.stderr
    return done


@pytest.fixture(scope="session")
def binary() -> Path:
    if not EOM.exists():
        pytest.fail(f"{EOM} is not built: run `cargo test --workspace` or set EOM_BIN")
    return EOM
