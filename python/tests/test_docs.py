"""docs/python.md's walk-through, run as a notebook runs it: its Python blocks in order in
one namespace, its `eom …` shell lines through the binary, in a folder with the repository's
scenes."""

from __future__ import annotations

import os
import re
import shlex

import pytest

from conftest import ROOT, eom_cli

BLOCK = re.compile(r"```(python|sh)\n(.*?)```", re.DOTALL)


def test_the_walk_through_runs(binary, tmp_path, monkeypatch):
    pytest.importorskip("matplotlib")
    pytest.importorskip("control")
    (tmp_path / "scenes").symlink_to(ROOT / "scenes")
    monkeypatch.chdir(tmp_path)
    namespace: dict = {}
    page = (ROOT / "docs" / "python.md").read_text()
    blocks = BLOCK.findall(page)
    assert sum(kind == "python" for kind, _ in blocks) >= 6
    for kind, code in blocks:
        if kind == "python":
            exec(compile(code, "docs/python.md", "exec"), namespace)
        else:
            for line in code.splitlines():
                if line.startswith("eom "):
                    eom_cli(*shlex.split(line)[1:])
    assert (tmp_path / "mariner_turn.png").stat().st_size > 1000
    assert os.path.exists(tmp_path / "mariner_nr" / "sweep.csv")
